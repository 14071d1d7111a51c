#pragma once

// The seam between the LSTM baseline's public face (LstmBaseline, in the engine) and its libtorch
// half (baselines/torch/, built as the module libdrytwin_lstm.so and loaded on first use).
//
// Why a module: linking libtorch into a program costs about one second of start-up on every run
// (its ~290 shared libraries are relocated and its operator registry filled before main), whether
// or not the LSTM is used. `drytwin inspect`, every test program and every CLI call in a script
// paid it. Behind this seam only the runs that train or load an LSTM do.

#include "baselines/LstmBaseline.h"

#include <memory>
#include <string>
#include <vector>

namespace drytwin::baselines {

/// @brief A follower's state: the network's cell state carried along a growing record.
class LstmFollowerState {
public:
    virtual ~LstmFollowerState() = default;
    virtual void advanceTo(const data::SiBatch& record, std::size_t row) = 0;
    virtual std::vector<residual::HybridPrediction>
    forecast(const std::vector<const data::SiBatch*>& candidates, int horizon) const = 0;
    virtual std::size_t lastRow() const = 0;
};

/// @brief A trained network and the record of its training (LstmBaseline's questions, answered by
/// the module).
class LstmNetwork {
public:
    virtual ~LstmNetwork() = default;
    virtual std::vector<residual::HybridPrediction>
    predictHorizons(const residual::BatchView& view, const std::vector<int>& horizons) const = 0;
    /// @brief A follower of this network; the network must outlive it.
    virtual std::unique_ptr<LstmFollowerState> follower() const = 0;
    virtual std::string toJson() const = 0;
    virtual double trainingSeconds() const = 0;
    virtual const std::vector<double>& lossHistory() const = 0;
    virtual const std::vector<LstmEpoch>& epochs() const = 0;
    virtual const LstmValidation& validation() const = 0;
    virtual const Ending& ending() const = 0;
};

/// @brief What the module exports (`drytwin_lstm_module`, C linkage). The interface version is
/// checked on loading: a module from another build of DryTwin is refused, not called.
struct LstmModuleEntry {
    int interfaceVersion = 0;
    Expected<std::unique_ptr<LstmNetwork>> (*train)(const std::vector<residual::BatchView>& training,
                                                    const LstmOptions& options,
                                                    const Progress& progress) = nullptr;
    Expected<std::unique_ptr<LstmNetwork>> (*fromJson)(const std::string& json) = nullptr;
};

inline constexpr int kLstmModuleInterfaceVersion = 1;
inline constexpr const char* kLstmModuleSymbol = "drytwin_lstm_module";

/// @brief The module, loaded once (thread-safe): from $DRYTWIN_LSTM_MODULE if set, else beside the
/// program, else ../lib/drytwin/ from it, else where the build put it. An error names every place
/// tried and why the last one failed.
Expected<const LstmModuleEntry*> lstmModule();

} // namespace drytwin::baselines
