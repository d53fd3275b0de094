// STEP assembly instancing bound (issue 22). A STEP assembly places products through
// NEXT_ASSEMBLY_USAGE_OCCURRENCE entities (ISO 10303-44 product structure: relating = the
// assembly's product definition, related = the placed one), and a sub-assembly may be placed
// any number of times at every level. OpenCASCADE's transfer builds a located shape for every
// expanded placement: a 66 KB file of 24 levels, each placing the level below twice (2^24
// boxes), ran past the readers' 600 s timeout. This scans the file's NAUO entities once (no
// full parse), counts the parts the assemblies expand to, and refuses the file before OCCT
// reads it.
//
// Counted: placed parts (products that place nothing) against limits.maxInstances. Placement
// through MAPPED_ITEM representation maps is not counted (OCCT bounds it by the file's size).
// Failure: Error(TooLarge) naming the file, the count and the limit; Error(Malformed) for an
// assembly that places itself. A file without such entities is left to the reader.
#pragma once

#include <filesystem>

#include "pipeline/io/ImportLimits.h"

namespace hlod {

void checkStepInstancing(const std::filesystem::path& file, const ImportLimits& limits);

} // namespace hlod
