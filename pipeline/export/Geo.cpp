#include "pipeline/export/Geo.h"

#include <cmath>
#include <sstream>

#include "pipeline/core/Error.h"

namespace hlod {

GeoLocation parseGeoLocation(const std::string& text) {
    std::istringstream in(text);
    GeoLocation g;
    char c1 = 0, c2 = 0;
    if (!(in >> g.latitudeDeg >> c1 >> g.longitudeDeg >> c2 >> g.heightM) || c1 != ',' ||
        c2 != ',' || !(in >> std::ws).eof()) {
        throw Error(ErrorCode::InvalidArgument,
                    "--geo expects lat,lon,height (degrees, degrees, metres), got '" + text + "'");
    }
    if (!std::isfinite(g.latitudeDeg) || std::abs(g.latitudeDeg) > 90.0 ||
        !std::isfinite(g.longitudeDeg) || std::abs(g.longitudeDeg) > 180.0 ||
        !std::isfinite(g.heightM) || std::abs(g.heightM) > 1e5) {
        throw Error(ErrorCode::InvalidArgument, "--geo position out of range: '" + text + "'");
    }
    return g;
}

glm::dmat4 enuToEcef(const GeoLocation& where) {
    constexpr double a = 6378137.0;         // WGS84 semi-major axis (m)
    constexpr double e2 = 6.69437999014e-3; // first eccentricity squared
    constexpr double deg = 3.14159265358979323846 / 180.0;
    const double lat = where.latitudeDeg * deg, lon = where.longitudeDeg * deg;
    const double sl = std::sin(lat), cl = std::cos(lat), so = std::sin(lon), co = std::cos(lon);
    const double n = a / std::sqrt(1.0 - e2 * sl * sl);
    const glm::dvec3 p((n + where.heightM) * cl * co, (n + where.heightM) * cl * so,
                       (n * (1.0 - e2) + where.heightM) * sl);
    const glm::dvec3 east(-so, co, 0.0);
    const glm::dvec3 north(-sl * co, -sl * so, cl);
    const glm::dvec3 up(cl * co, cl * so, sl);
    return glm::dmat4(glm::dvec4(east, 0.0), glm::dvec4(north, 0.0), glm::dvec4(up, 0.0),
                      glm::dvec4(p, 1.0));
}

} // namespace hlod
