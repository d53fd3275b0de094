// Numbers as people read them in the editor's tables (issue 20 #5): counts with digit grouping
// and, when large, a short form; volumes and sizes with a unit that keeps them between 1 and
// 1000; never scientific notation. All in the user's locale (decimal and group separators).
#pragma once

#include <cstdint>

#include <QString>

namespace hlod::widgets {

// Three significant digits, no exponent, no trailing zeros: 1.23, 12.3, 123, 1,235.
QString formatSignificant(double x);
// 987 -> "987", 12345 -> "12,345", 123456 -> "123 k", 1234567 -> "1.23 M".
QString formatCount(std::uint64_t n);
// Cubic metres, shown in m³, L (litres), cm³ or mm³ with three significant digits:
// 0.0042 -> "4.2 L", 3.5e-7 -> "350 mm³", 12345.6 -> "12,346 m³".
QString formatVolume(double cubicMetres);
// Metres with a unit that keeps them readable, three significant digits: "1.2 km", "3.4 m",
// "12 cm", "0.8 mm".
QString formatLength(double metres);
// Bytes in MB (10^6 bytes) with two decimals below 100 MB: "3.41 MB", "812 MB".
QString formatMegabytes(std::uint64_t bytes);

} // namespace hlod::widgets
