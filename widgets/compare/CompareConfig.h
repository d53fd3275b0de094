// One side of the comparison view (issue #7 "side-by-side comparison"): the few parameters a
// technical artist varies when comparing clusterings (the thesis compares sphere against AABB
// with k = 0, 1, 2 in its tables 6.2-6.6), laid over the document's full settings.
//
// A CompareConfig holds the clustering volume, the AABB proportion exponent k and the screen
// size S; everything else (proxy method, pixel error, max children, hand edits, proxy cache)
// comes from the base HlodSettings, so both sides differ only in what the user chose.
// Text form (command line `--compare LEFT:RIGHT`): "sphere", "octree", "original", "aabb"
// (k of the base), "aabb-k2" / "aabb-k0.5"; "current" is the base's own values; any of them may
// end in "@S" to set the screen size in pixels ("aabb-k2@400"). Nothing here throws: parsing
// returns false with a message naming what is wrong.
#pragma once

#include <utility>

#include <QString>

#include "pipeline/doc/HlodBuild.h"

namespace hlod::widgets {

struct CompareConfig {
    VolumeType volume = VolumeType::Sphere;
    double k = 1.0;            // used by AABB only
    double screenSize = 300.0; // S, pixels
    bool operator==(const CompareConfig&) const = default;
};

// The configuration `settings` already has.
CompareConfig configOf(const HlodSettings& settings);
// `base` with the volume, k and screen size of `config` (k is carried for every volume, so a
// sphere side's settings do not change when the document's k does; only AABB uses it).
HlodSettings applyConfig(const HlodSettings& base, const CompareConfig& config);
// "Sphere", "AABB k=2", "Octree", "Original hierarchy", followed by ", S = 400 px" when
// `withScreenSize`.
QString configLabel(const CompareConfig& config, bool withScreenSize = false);
// The text form (see above) of `config`, always with its screen size.
QString configSpec(const CompareConfig& config);

// Parses the text form over `base`; false with `error` set when `text` is not one.
bool parseConfig(const QString& text, const HlodSettings& base, CompareConfig& out,
                 QString* error = nullptr);
// "LEFT:RIGHT".
bool parseConfigPair(const QString& text, const HlodSettings& base,
                     std::pair<CompareConfig, CompareConfig>& out, QString* error = nullptr);

// What the view opens with: left = the document's settings, right = AABB k=2 (sphere when the
// document already uses AABB), at the document's screen size.
std::pair<CompareConfig, CompareConfig> defaultConfigs(const HlodSettings& document);

// Whether two settings build the same HLOD (every declared parameter and the hand edits agree).
bool sameSettings(const HlodSettings& a, const HlodSettings& b);

} // namespace hlod::widgets
