// Numbers as people read them in the editor's tables (issue 20 #5): counts with digit grouping
// and, when large, a short form; volumes and sizes with a unit that keeps them between 1 and
// 1000; never scientific notation.
// Lengths in scene units, bytes in MB (10^6) everywhere in the editor (issue 31 #6). All in the
// user's locale (decimal and group separators).
#pragma once

#include <cstdint>

#include <QString>

namespace hlod::widgets {

// Three significant digits, no exponent, no trailing zeros: 1.23, 12.3, 123, 1,235.
QString formatSignificant(double x);
// 987 -> "987", 12345 -> "12,345", 123456 -> "123 k", 1234567 -> "1.23 M".
QString formatCount(std::uint64_t n);
// Lengths and volumes are in scene units (issue 31 #6): the scene says nothing about its unit
// (glTF is metres, AC3D and CAD exports are whatever their author used), so the editor shows
// every length in the same unit, the scene's, with no m/cm/km switching that would put "910 m"
// beside "12 cm" for the same scene. Columns name the unit in their header (kLengthUnit).
// Three significant digits, never an exponent: 1234 -> "1,234", 80.25 -> "80.3",
// 0.12 -> "0.12", 0.0008 -> "0.0008".
QString formatLength(double sceneUnits);
// Cubic scene units, as formatLength: "12,346", "1.5", "0.0042".
QString formatVolume(double cubicSceneUnits);
// "scene units", the unit formatLength's numbers are in.
QString lengthUnit();
// Bytes in MB (10^6 bytes; the one byte unit of the editor) with two decimals below 100 MB:
// "3.41 MB", "812 MB".
QString formatMegabytes(std::uint64_t bytes);

} // namespace hlod::widgets
