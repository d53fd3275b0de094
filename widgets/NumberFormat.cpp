// Number formatting for the editor's tables (see NumberFormat.h).
#include "widgets/NumberFormat.h"

#include <algorithm>
#include <cmath>

#include <QCoreApplication>
#include <QLocale>

namespace hlod::widgets {

QString formatSignificant(double x) {
    const QLocale locale;
    if (x >= 999.5) return locale.toString(std::llround(x));
    const int decimals = x >= 99.95 ? 0 : x >= 9.995 ? 1 : 2;
    QString text = locale.toString(x, 'f', decimals);
    if (decimals > 0) {
        const QChar point = locale.decimalPoint().at(0);
        while (text.endsWith(QLatin1Char('0')))
            text.chop(1);
        if (text.endsWith(point)) text.chop(1);
    }
    return text;
}

QString formatCount(std::uint64_t n) {
    const QLocale locale;
    if (n < 100000) return locale.toString(static_cast<qulonglong>(n));
    if (n < 1000000)
        return QCoreApplication::translate("NumberFormat", "%1 k").arg(formatSignificant(n / 1e3));
    return QCoreApplication::translate("NumberFormat", "%1 M").arg(formatSignificant(n / 1e6));
}

namespace {

// Three significant digits at any size, no exponent, no trailing zeros.
QString threeDigits(double x) {
    if (!(x > 0.0)) return QStringLiteral("0");
    if (x >= 0.995) return formatSignificant(x);
    const int decimals = std::min(12, 2 - static_cast<int>(std::floor(std::log10(x))));
    const QLocale locale;
    QString text = locale.toString(x, 'f', decimals);
    const QChar point = locale.decimalPoint().at(0);
    while (text.endsWith(QLatin1Char('0')))
        text.chop(1);
    if (text.endsWith(point)) text.chop(1);
    return text;
}

} // namespace

QString formatVolume(double v) { return threeDigits(v); }

QString formatLength(double length) { return threeDigits(length); }

QString lengthUnit() { return QCoreApplication::translate("NumberFormat", "scene units"); }

QString formatMegabytes(std::uint64_t bytes) {
    const double mb = static_cast<double>(bytes) / 1e6;
    return QLocale().toString(mb, 'f', mb < 100.0 ? 2 : 0) + QStringLiteral(" MB");
}

} // namespace hlod::widgets
