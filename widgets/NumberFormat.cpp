// Number formatting for the editor's tables (see NumberFormat.h).
#include "widgets/NumberFormat.h"

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

QString formatVolume(double v) {
    if (!(v > 0.0)) return QStringLiteral("0 m³");
    if (v >= 1.0) return formatSignificant(v) + QStringLiteral(" m³");
    if (v >= 1e-3) return formatSignificant(v * 1e3) + QStringLiteral(" L");
    if (v >= 1e-6) return formatSignificant(v * 1e6) + QStringLiteral(" cm³");
    return formatSignificant(v * 1e9) + QStringLiteral(" mm³");
}

QString formatLength(double m) {
    if (!(m > 0.0)) return QStringLiteral("0 m");
    if (m >= 1000.0) return formatSignificant(m / 1000.0) + QStringLiteral(" km");
    if (m >= 1.0) return formatSignificant(m) + QStringLiteral(" m");
    if (m >= 0.01) return formatSignificant(m * 100.0) + QStringLiteral(" cm");
    return formatSignificant(m * 1000.0) + QStringLiteral(" mm");
}

QString formatMegabytes(std::uint64_t bytes) {
    const double mb = static_cast<double>(bytes) / 1e6;
    return QLocale().toString(mb, 'f', mb < 100.0 ? 2 : 0) + QStringLiteral(" MB");
}

} // namespace hlod::widgets
