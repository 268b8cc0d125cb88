#pragma once
// What the viewport draws besides the bodies. A view preference, not part of the scene: changing
// it is not an edit and never dirties the document. A QObject so the QML settings panel binds to it.

#include <QObject>

namespace interplay {

class DebugDrawOptions : public QObject {
    Q_OBJECT
    Q_PROPERTY(bool aabbs MEMBER m_aabbs NOTIFY changed)
    Q_PROPERTY(bool contactPoints MEMBER m_contactPoints NOTIFY changed)
    Q_PROPERTY(bool contactNormals MEMBER m_contactNormals NOTIFY changed)
    Q_PROPERTY(bool sleepingTint MEMBER m_sleepingTint NOTIFY changed)

public:
    using QObject::QObject;

    bool aabbs() const { return m_aabbs; }
    bool contactPoints() const { return m_contactPoints; }
    bool contactNormals() const { return m_contactNormals; }
    bool sleepingTint() const { return m_sleepingTint; }

signals:
    void changed();

private:
    bool m_aabbs = false;
    bool m_contactPoints = false;
    bool m_contactNormals = false;
    bool m_sleepingTint = true;  // sleeping bodies drawn greyed, so sleep is visible at a glance
};

}  // namespace interplay
