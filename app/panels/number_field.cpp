#include "app/panels/number_field.h"

#include <QKeyEvent>
#include <QLocale>
#include <QStyle>
#include <QStyleOptionFrame>

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
    updateToolTip();
}

void NumberField::setValue(std::optional<double> value) {
    m_value = value;
    showValue();
    setPlaceholderText(value ? QString() : tr("mixed"));
}

QString NumberField::display() const {
    if (!m_value) return {};
    // Scene files use '.' whatever the locale; so do the fields. Six digits hide float noise (29.99999).
    // + 0.0 shows a negative zero (a computed axis, say) as "0". Fewer digits where six do not fit
    // the field, so that it never shows a number cut to its tail ("9314e-06"); the tooltip has six.
    const double value = *m_value + 0.0;
    QString text;
    for (int digits = kDigits; digits >= kFewestDigits; --digits) {
        text = QLocale::c().toString(value, 'g', digits);
        if (fontMetrics().horizontalAdvance(text) <= textWidth()) break;
    }
    return text;
}

int NumberField::textWidth() const {
    QStyleOptionFrame option;
    initStyleOption(&option);
    const QRect contents = style()->subElementRect(QStyle::SE_LineEditContents, &option, this);
    constexpr int kLineEditMargin = 2;  // QLineEdit's own horizontal padding on each side
    return contents.marginsRemoved(textMargins()).width() - 2 * kLineEditMargin;
}

void NumberField::showValue() {
    m_shown = display();
    setText(m_shown);
    updateToolTip();
}

void NumberField::updateToolTip() {
    setToolTip(m_value ? tr("%1: %2, from %3 to %4")
                             .arg(m_quantity, QLocale::c().toString(*m_value + 0.0, 'g', kDigits))
                             .arg(m_minimum)
                             .arg(m_maximum)
                       : tr("%1, from %2 to %3").arg(m_quantity).arg(m_minimum).arg(m_maximum));
}

void NumberField::resizeEvent(QResizeEvent* event) {
    QLineEdit::resizeEvent(event);
    if (text() == m_shown) showValue();  // not while the user's own text is in the field
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
    if (event->key() == Qt::Key_Escape && text() != m_shown) {
        showValue();
        event->accept();
        return;
    }
    QLineEdit::keyPressEvent(event);
}

void NumberField::commit() {
    if (text() == m_shown) {
        showValue();  // forgets typing that came back to the value: Ctrl+Z is the document's
        return;
    }
    if (text().trimmed().isEmpty() && !m_value) return;  // left a mixed field empty: no change
    const auto parsed = parse(text());
    if (const QString* message = std::get_if<QString>(&parsed)) {
        showValue();
        emit rejected(*message);
        return;
    }
    emit committed(std::get<double>(parsed));
}

}  // namespace interplay
