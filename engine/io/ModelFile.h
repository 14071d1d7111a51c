#pragma once

#include "common/Error.h"
#include "hybrid/HybridModel.h"
#include "plant/VirtualPlant.h"

#include <map>

#include <string>

namespace drytwin::io {

/// @brief Current version of the model-file format. Version 2 groups the learnt models under
/// "residual_models" and adds "mechanisms"; version 1 files (learnt models at the top level)
/// are read as well.
inline constexpr int kModelFormatVersion = 2;

/// @brief Reads and validates a model file, parsing every stored model once; errors name the
/// file and the key (exit code 3).
Expected<hybrid::HybridModel> readModelFile(const std::string& path);
/// @brief Parses model-file text; @p name is used in messages.
Expected<hybrid::HybridModel> parseModelFile(const std::string& text, const std::string& name);
/// @brief Writes a model file atomically (format version 2).
Status writeModelFile(const hybrid::HybridModel& model, const std::string& path);
/// @brief The model-file text of @p model.
std::string formatModelFile(const hybrid::HybridModel& model);
/// @brief Sixteen hex digits that change when anything of @p model its file holds changes (the
/// physics parameters, the learnt models): which model a training session's MPCs ran on.
std::string modelFingerprint(const hybrid::HybridModel& model);

/// @brief The `--truth` file of `generate`: the plant's parameters and effects, which plant wrote
/// the data and how its sensors read (CONTRACT.md §2).
std::string truthJson(const plant::PlantOptions& options, const plant::PlantResult& result);

} // namespace drytwin::io
