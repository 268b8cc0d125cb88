#include "app/panels/number_field.h"

#include <QKeyEvent>
#include <QLocale>

#include <cmath>

namespace interplay {

NumberField::NumberField(QString quantity, double minimum, double maximum, QWidget* parent)
    : QLineEdit(parent), m_quantity(std::move(quantity)), m_minimum(minimum), m_maximum(maximum) {
    setAlignment(Qt::AlignRight);
    setMinimumWidth(40);
    setRange(minimum, maximum);
    connect(this, &QLineEdit::editingFinished, this, &NumberField::commit);
}

void NumberField::setRange(double minimum, double maximum) {
    m_minimum = minimum;
    m_maximum = maximum;
    setToolTip(tr("%1, from %2 to %3").arg(m_quantity).arg(minimum).arg(maximum));
}

void NumberField::setValue(std::optional<double> value) {
    m_value = value;
    setText(display());
    setPlaceholderText(value ? QString() : tr("mixed"));
}

QString NumberField::display() const {
    // Scene files use '.' whatever the locale; so do the fields. Six digits hide float noise (29.99999).
    // + 0.0 shows a negative zero (a computed axis, say) as "0".
    return m_value ? QLocale::c().toString(*m_value + 0.0, 'g', 6) : QString();
}

std::variant<double, QString> NumberField::parse(const QString& text) const {
    bool ok = false;
    const double number = QLocale::c().toDouble(text.trimmed(), &ok);
    if (!ok || !std::isfinite(number)) {
        return tr("%1: \"%2\" is not a number.").arg(m_quantity, text.trimmed());
    }
    if (number < m_minimum || number > m_maximum) {
        return tr("%1 must be between %2 and %3; %4 is not accepted.")
            .arg(m_quantity)
            .arg(m_minimum)
            .arg(m_maximum)
            .arg(number);
    }
    return number;
}

void NumberField::keyPressEvent(QKeyEvent* event) {
    if (event->key() == Qt::Key_Escape && text() != display()) {
        setText(display());
        event->accept();
        return;
    }
    QLineEdit::keyPressEvent(event);
}

void NumberField::commit() {
    if (text() == display()) {
        setText(display());  // forgets typing that came back to the value: Ctrl+Z is the document's
        return;
    }
    if (text().trimmed().isEmpty() && !m_value) return;  // left a mixed field empty: no change
    const auto parsed = parse(text());
    if (const QString* message = std::get_if<QString>(&parsed)) {
        setText(display());
        emit rejected(*message);
        return;
    }
    emit committed(std::get<double>(parsed));
}

}  // namespace interplay
