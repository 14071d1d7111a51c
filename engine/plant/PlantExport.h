#pragma once

#include "data/Batch.h"
#include "data/SiBatch.h"
#include "physics/LineInputs.h"
#include "plant/VirtualPlant.h"

namespace drytwin::plant {

/// @brief A plant batch as its batch file would hold it (file units, instrument resolution:
/// 0.001 % for moisture, 0.01 °C, 0.1 kg/h ...), with `# batch:` and `# source:` metadata.
data::Batch toBatch(const PlantBatch& pb, unsigned seed);

/// @brief The plant's batches as a loaded, cleaned data set in SI units: what reading the
/// files `generate` writes would give (same rounding), without the files.
std::vector<data::SiBatch> toSiBatches(const PlantResult& result, unsigned seed);

/// @brief The model's input series of a plant batch (as recorded, full precision).
physics::LineInputs toLineInputs(const PlantBatch& pb);

} // namespace drytwin::plant
