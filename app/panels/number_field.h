#pragma once
// A line edit for one number with an accepted range. Commits on Enter or focus loss: a value in
// range is emitted by committed(); anything else (not a number, NaN, infinity, out of range) is
// refused with a sentence saying why, through rejected(), and the field shows its value again.
// An unchanged text commits nothing, so tabbing through fields never creates history entries.
// Escape drops typed text and shows the value again, committing nothing.

#include <QLineEdit>

#include <optional>
#include <variant>

namespace interplay {

class NumberField : public QLineEdit {
    Q_OBJECT

public:
    NumberField(QString quantity, double minimum, double maximum, QWidget* parent = nullptr);

    // The accepted range, when it depends on another field (mass or density).
    void setRange(double minimum, double maximum);

    // Shows `value`; without a value the field is empty (several bodies that differ).
    void setValue(std::optional<double> value);
    std::optional<double> value() const { return m_value; }

    // Parses `text` as this field would: the number, or the reason it is refused.
    std::variant<double, QString> parse(const QString& text) const;

signals:
    void committed(double value);
    void rejected(const QString& message);

protected:
    void keyPressEvent(QKeyEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    void commit();
    // The value as the field shows it: six significant digits, or as many as fit its width.
    QString display() const;
    int textWidth() const;  // pixels the text has inside the frame
    void showValue();       // shows display(), and the full value in the tooltip
    void updateToolTip();   // the quantity, its value to six digits and the accepted range

    static constexpr int kDigits = 6;
    static constexpr int kFewestDigits = 2;

    QString m_quantity;  // what the number is, for messages: "Friction", "Radius"
    double m_minimum, m_maximum;
    std::optional<double> m_value;
    QString m_shown;  // the text showValue() put in the field: anything else is the user's
};

}  // namespace interplay
