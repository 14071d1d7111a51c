// When a request to the Session is well formed: the validate() of each action's options that the
// header does not define inline, with the readable error each returns, and the parameters a
// calibration frees unless told otherwise. Nothing here looks at the session's data or model.

#include "workflow/Session.h"

namespace drytwin::workflow {

Status OpenOptions::validate() const {
    if (dataPath.empty() && modelPath.empty()) {
        return invalidOption("data", "give a data path, a model path or both");
    }
    if (auto st = cleaning.validate(); !st) {
        return invalidOption(st.error().place, st.error().reason);
    }
    return {};
}

Status GenerateOptions::validate() const {
    if (outFolder.empty()) {
        return invalidOption("out", "an output folder is needed");
    }
    if (auto st = plant.validate(); !st) {
        return invalidOption(st.error().place, st.error().reason);
    }
    // A batch file holds `samples` rows 1 s apart: an onset at or after its end would write a
    // truth file claiming an effect that no row shows.
    for (const auto& [m, onset] : plant.effectOnsetS) {
        if (onset >= plant.samples) {
            return invalidOption("onset " + std::string(plant::info(m).name),
                                 "at " + std::to_string(static_cast<long long>(onset)) +
                                     " s it lies after each batch's end (" + std::to_string(plant.samples) +
                                     " samples, 1 s apart): no row would show the mechanism");
        }
    }
    return {};
}

std::vector<properties::Param> defaultCalibrationParameters() {
    return {properties::Param::h_HDT, properties::Param::k_HDT, properties::Param::phi_X_in_scatter};
}

Status CalibrateOptions::validate() const {
    if (subsetStride == 0) {
        return invalidOption("subset", "the stride must be at least 1");
    }
    return calibration.validate();
}

Status TrainOptions::validate() const {
    if (auto st = residual.validate(); !st) {
        return invalidOption(st.error().place, st.error().reason);
    }
    if (auto st = selection.validate(); !st) {
        return st;
    }
    return lstm.validate();
}

Status PipelineOptions::validate() const {
    if (outFolder.empty()) {
        return invalidOption("out", "an output folder is needed");
    }
    if (auto st = calibrate.validate(); !st) {
        return st;
    }
    if (auto st = train.validate(); !st) {
        return st;
    }
    if (auto st = evaluate.validate(); !st) {
        return st;
    }
    return discover.validate();
}

Status TrainingOptions::validate() const {
    if (scriptPath.empty()) {
        return invalidOption("--script", "a session file is needed");
    }
    if (outFolder.empty()) {
        return invalidOption("--out", "an output folder is needed");
    }
    return {};
}

} // namespace drytwin::workflow
