// Error budget and switching distance of an HLOD node, from the screen-size threshold of the
// thesis (Wiberg 2018, 2.2.1 and 5.3: Simplygon's "maximum screen size" fixed at 300 pixels).
//
// A node is drawn instead of its children when its projected bounding diameter is at most S
// pixels. At that switch point one pixel covers diameter / S metres, so a proxy that deviates
// at most e = t * diameter / S metres from what it replaces deviates at most t pixels on screen.
// With a perspective camera of vertical field of view fov and a viewport H pixels high, a sphere
// of diameter D seen at distance d covers about D * H / (2 d tan(fov/2)) pixels, so the node
// switches at d = D * H / (2 S tan(fov/2)).
//
// Units: diameters, errors and distances in metres; sizes in pixels; fov in degrees.
#pragma once

#include "pipeline/cluster/ClusterTree.h"

namespace hlod {

struct ScreenParams {
    double screenSize = 300.0;      // S: projected diameter (px) at which a node switches
    double pixelError = 1.0;        // t: allowed proxy deviation at the switch point (px)
    double fovYDegrees = 60.0;      // vertical field of view of the reference camera
    double viewportHeight = 1080.0; // viewport height (px) of the reference camera
};

// Throws Error(InvalidArgument) naming the parameter when the formulas below are undefined for
// it: S, t and H must be positive, fov within (0, 180) degrees. The ranges a user may choose are
// the parameter declarations' (pipeline/graph/Parameters.cpp), checked where values enter.
void validate(const ScreenParams& params);

// Diameter of a node's bounding sphere; the box diagonal when the sphere is unset (radius 0).
double nodeDiameter(const ClusterNode& node);

// e = t * diameter / S (metres).
double proxyErrorBudget(double diameter, const ScreenParams& params);

// Camera distance (metres) at which the node's projected diameter equals S.
double switchDistance(double diameter, const ScreenParams& params);

} // namespace hlod
