// Placement of a package on the globe: the local east-north-up frame at a WGS84 position,
// as the 3D Tiles root transform (OGC 3D Tiles 1.1, 5.3 "Coordinate reference system"; WGS84
// ellipsoid constants from NIMA TR8350.2).
#pragma once

#include <optional>
#include <string>

#include <glm/glm.hpp>

namespace hlod {

struct GeoLocation {
    double latitudeDeg = 0.0;
    double longitudeDeg = 0.0;
    double heightM = 0.0;
};

// Parses "lat,lon,height" (degrees, degrees, metres); throws Error(InvalidArgument) when the
// text is malformed or out of range (|lat| <= 90, |lon| <= 180, |height| <= 1e5).
GeoLocation parseGeoLocation(const std::string& text);

// Column-major 4x4 ENU->ECEF matrix: columns east, north, up, position.
glm::dmat4 enuToEcef(const GeoLocation& where);

} // namespace hlod
