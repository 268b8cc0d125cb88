#pragma once
// What the Inspector's body and joint forms (inspector_panel.cpp, inspector_joint_rows.cpp) share:
// the accepted ranges of their fields and how a check box shows a selection.

#include "simcore/settings_schema.h"

#include <QCheckBox>

#include <optional>
#include <string_view>

namespace interplay::inspector {

// Accepted ranges: the scene format's (simcore/settings_schema.h), so the editor lets in nothing a
// file would refuse on load. Each field names the schema properties it edits (its "schemaKeys"),
// which test_settings_schema checks against the schema.
using simcore::PropertyOwner;
inline const simcore::NumberRange& range(PropertyOwner owner, std::string_view key) {
    return simcore::propertyRange(owner, key);
}

// A value the selection shares, or a partly checked box where it differs. The third state is for
// showing only: a click sets every selected object, and they agree again.
inline void showSharedCheck(QCheckBox* box, std::optional<bool> shared) {
    if (shared) {
        box->setTristate(false);
        box->setChecked(*shared);
    } else {
        box->setCheckState(Qt::PartiallyChecked);
    }
}

}  // namespace interplay::inspector
