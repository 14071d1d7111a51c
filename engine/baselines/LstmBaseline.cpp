#include "baselines/LstmBaseline.h"

#include "baselines/LstmNetwork.h"

// LstmBaseline's public face: every question goes to the network the libtorch module made
// (LstmNetwork.h says why it is a module).

namespace drytwin::baselines {

namespace {
constexpr std::size_t kNoRow = static_cast<std::size_t>(-1);
} // namespace

struct LstmBaseline::Impl {
    std::unique_ptr<LstmNetwork> network; ///< null only in a default-constructed (untrained) baseline
};

LstmBaseline::LstmBaseline() : m_impl(std::make_unique<Impl>()) {}
LstmBaseline::~LstmBaseline() = default;
LstmBaseline::LstmBaseline(LstmBaseline&&) noexcept = default;
LstmBaseline& LstmBaseline::operator=(LstmBaseline&&) noexcept = default;

Expected<LstmBaseline> LstmBaseline::train(const std::vector<residual::BatchView>& training,
                                           const LstmOptions& options, const Progress& progress) {
    if (auto st = options.validate(); !st) {
        return st.error();
    }
    auto module = lstmModule();
    if (!module) {
        return module.error();
    }
    auto network = (*module)->train(training, options, progress);
    if (!network) {
        return network.error();
    }
    LstmBaseline model;
    model.m_impl->network = std::move(*network);
    return model;
}

Expected<LstmBaseline> LstmBaseline::fromJson(const std::string& json) {
    auto module = lstmModule();
    if (!module) {
        return module.error();
    }
    auto network = (*module)->fromJson(json);
    if (!network) {
        return network.error();
    }
    LstmBaseline model;
    model.m_impl->network = std::move(*network);
    return model;
}

residual::HybridPrediction LstmBaseline::predictAhead(const residual::BatchView& view, int horizon) const {
    return predictHorizons(view, {horizon}).front();
}

std::vector<residual::HybridPrediction>
LstmBaseline::predictHorizons(const residual::BatchView& view, const std::vector<int>& horizons) const {
    if (!m_impl->network) {
        return std::vector<residual::HybridPrediction>(horizons.size(),
                                                       residual::HybridPrediction::unknown(view.rows.size()));
    }
    return m_impl->network->predictHorizons(view, horizons);
}

std::string LstmBaseline::toJson() const {
    return m_impl->network ? m_impl->network->toJson() : std::string("{}");
}

double LstmBaseline::trainingSeconds() const {
    return m_impl->network ? m_impl->network->trainingSeconds() : 0.0;
}

const std::vector<double>& LstmBaseline::lossHistory() const {
    static const std::vector<double> none;
    return m_impl->network ? m_impl->network->lossHistory() : none;
}

const std::vector<LstmEpoch>& LstmBaseline::epochs() const {
    static const std::vector<LstmEpoch> none;
    return m_impl->network ? m_impl->network->epochs() : none;
}

const LstmValidation& LstmBaseline::validation() const {
    static const LstmValidation none;
    return m_impl->network ? m_impl->network->validation() : none;
}

const Ending& LstmBaseline::ending() const {
    static const Ending none;
    return m_impl->network ? m_impl->network->ending() : none;
}

struct LstmBaseline::Follower::State {
    std::unique_ptr<LstmFollowerState> follower; ///< null for an untrained baseline
};

LstmBaseline::Follower::Follower(const LstmBaseline& model)
    : m_model(&model), m_state(std::make_unique<State>()) {
    if (model.m_impl->network) {
        m_state->follower = model.m_impl->network->follower();
    }
}
LstmBaseline::Follower::~Follower() = default;
LstmBaseline::Follower::Follower(Follower&&) noexcept = default;

void LstmBaseline::Follower::advanceTo(const data::SiBatch& record, std::size_t row) {
    if (m_state->follower) {
        m_state->follower->advanceTo(record, row);
    }
}

std::vector<residual::HybridPrediction>
LstmBaseline::Follower::forecast(const std::vector<const data::SiBatch*>& candidates, int horizon) const {
    if (!m_state->follower) {
        return std::vector<residual::HybridPrediction>(
            candidates.size(),
            residual::HybridPrediction::unknown(static_cast<std::size_t>(std::max(0, horizon))));
    }
    return m_state->follower->forecast(candidates, horizon);
}

std::size_t LstmBaseline::Follower::lastRow() const {
    return m_state->follower ? m_state->follower->lastRow() : kNoRow;
}

} // namespace drytwin::baselines
