#pragma once

#include "common/Error.h"

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace drytwin::properties {

/// @brief Every parameter of the line model. Symbols follow the paper without backslashes and
/// braces (θ_{xe1} → theta_xe1), as model files key them (CONTRACT.md §2).
enum class Param {
    R_gas,
    R_water,
    theta_Cp1,
    theta_Cp2,
    theta_aw1,
    theta_xe1,
    theta_xe2,
    theta_xe3,
    theta_D0,
    theta_Ea,
    theta_Lv_aw,
    theta_D_RH,
    rho_mat,
    r,
    L_t,
    h_HDT,
    k_HDT,
    w,
    P_total,
    T_ref,
    chi_layer,
    L_char,
    h_conveyor,
    A_exp,
    beta_top,
    kappa,
    h_winnower,
    t_W,
    tau_HDT,
    tau_conv,
    tau_act,
    /// Mixing between the tube's outlet and the line's outlet (the belt's axial mixing, the
    /// winnower's holdup), as a first-order lag on X_out and T_out; 0: the paper's plug flow.
    /// Part of the model's structure, not a cause: discovery frees it with h_HDT and k_HDT.
    tau_mix,
    // Mechanism extensions of CONTRACT.md §4 (discovery): 0 gives back the paper's model.
    theta_wall,     ///< tube_wall_heat_loss
    theta_gas,      ///< gas_phase_coupling
    theta_foul,     ///< heat_transfer_fouling
    tau_meter,      ///< moisture_meter_lag
    X_meter_offset, ///< moisture_meter_offset
    dtau_conv,      ///< transport_delay_error
    theta_fall,     ///< falling_rate_drying
    theta_reabs,    ///< ambient_reabsorption
    // Sensor causes (CONTRACT.md §4): the measured inputs are not the truth, and the model can
    // say so. Each corrects a measured input before the line sees it; 0: the input as measured.
    X_in_offset,      ///< inlet_moisture_sensor_offset
    tau_hot_sensor,   ///< hot_air_sensor_lag
    phi_X_in_scatter, ///< inlet_moisture_sensor_noise
    /// Onset of the mechanisms above, in seconds since each batch's start (0: from the start). Set
    /// by discovery when a cause starts mid-batch; one onset shared by every mechanism.
    t_onset,
};
inline constexpr int kParamCount = 44;
/// @brief The first mechanism-extension parameter; the eleven from here on are, in order, the
/// mechanisms of CONTRACT.md §4.
inline constexpr Param kFirstMechanismParam = Param::theta_wall;
inline constexpr int kMechanismParamCount = 11;

/// @brief One row of the parameter table: symbol, meaning, unit, default, bounds, source.
struct ParameterInfo {
    Param id;
    std::string_view symbol;
    std::string_view meaning;
    std::string_view unit;
    double defaultValue;
    double lower;
    double upper;
    std::string_view source; ///< "paper App. A", "paper §IV.C", or the engineering reason
    bool fixed;              ///< physical constant: never freed in calibration
    bool duration;           ///< a residence or lag time: changes integration windows, not rates
};

/// @brief The whole table, in enum order.
const std::array<ParameterInfo, kParamCount>& parameterTable();
const ParameterInfo& info(Param p);
/// @brief " unit" to follow a value of @p p in a sentence, or nothing for a dimensionless one
/// ("0.164" rather than "0.164 -", which read as a dangling minus).
std::string spacedUnit(Param p);
std::optional<Param> paramBySymbol(std::string_view symbol);

/// @brief The CONTRACT.md §4 mechanism a parameter extends the model by, if any.
std::optional<std::string_view> mechanismOf(Param p);
/// @brief The parameter of a CONTRACT.md §4 mechanism, by its contract name.
std::optional<Param> mechanismParam(std::string_view mechanism);
/// @brief Every mechanism-extension parameter, in CONTRACT.md §4 order.
const std::vector<Param>& mechanismParams();

/// @brief Values of every parameter, indexed by Param. Defaults from the table.
/// Stored contiguously so that CVODES can perturb them in place for sensitivities.
class ParameterSet {
public:
    ParameterSet();
    double operator[](Param p) const { return m_values[static_cast<std::size_t>(p)]; }
    double& operator[](Param p) { return m_values[static_cast<std::size_t>(p)]; }
    double* data() { return m_values.data(); }
    const double* data() const { return m_values.data(); }
    /// @brief Every value finite and inside its bounds; the error names the parameter.
    Status validate() const;

private:
    std::array<double, kParamCount> m_values{}; // a value type: copies need no allocation
};

} // namespace drytwin::properties
