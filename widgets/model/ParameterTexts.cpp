#include "model/ParameterTexts.h"

#include "common/DisplayNames.h"

#include <QCoreApplication>
#include <string>

namespace drytwin::widgets {

namespace {

// The engine's parameter texts (engine/properties/Parameters.cpp), listed here so that lupdate
// finds them; translate() looks each up by its English text. A text missing here stays English,
// which test_mainwindow's parameterTextsAreTranslated catches.
[[maybe_unused]] const char* const kTexts[] = {
    QT_TRANSLATE_NOOP("ParameterTexts", "ideal gas constant"),
    QT_TRANSLATE_NOOP("ParameterTexts", "specific gas constant of water vapour"),
    QT_TRANSLATE_NOOP("ParameterTexts", "specific heat of dry material"),
    QT_TRANSLATE_NOOP("ParameterTexts", "specific heat of water"),
    QT_TRANSLATE_NOOP("ParameterTexts", "temperature parameter of water activity (Eq. 2)"),
    QT_TRANSLATE_NOOP("ParameterTexts", "Oswin parameter 1 (Eq. 5)"),
    QT_TRANSLATE_NOOP("ParameterTexts", "Oswin parameter 2 (Eq. 5), per kelvin of T in °C"),
    QT_TRANSLATE_NOOP("ParameterTexts", "Oswin parameter 3 (Eq. 5)"),
    QT_TRANSLATE_NOOP("ParameterTexts", "diffusivity pre-factor (Eq. 6)"),
    QT_TRANSLATE_NOOP("ParameterTexts", "activation energy of diffusion (Eq. 6)"),
    QT_TRANSLATE_NOOP("ParameterTexts", "bound-water latent heat correction (Eq. 4)"),
    QT_TRANSLATE_NOOP("ParameterTexts", "humidity reduction of diffusivity (Eq. 6)"),
    QT_TRANSLATE_NOOP("ParameterTexts", "particle density of the material (Eq. 7)"),
    QT_TRANSLATE_NOOP("ParameterTexts", "strand radius as a cylinder (Eq. 7)"),
    QT_TRANSLATE_NOOP("ParameterTexts", "strand length (Eq. 7)"),
    QT_TRANSLATE_NOOP("ParameterTexts", "convective heat-transfer coefficient in the tube (Eq. 8)"),
    QT_TRANSLATE_NOOP("ParameterTexts", "mass-transfer coefficient in the tube (Eq. 10)"),
    QT_TRANSLATE_NOOP("ParameterTexts", "humidity ratio of the drying air (Eq. 9)"),
    QT_TRANSLATE_NOOP("ParameterTexts", "total pressure of the drying air (Eq. 9)"),
    QT_TRANSLATE_NOOP("ParameterTexts", "enthalpy reference temperature (Eqs. 12, 14, 19)"),
    QT_TRANSLATE_NOOP("ParameterTexts", "layer packing factor (Eq. 13)"),
    QT_TRANSLATE_NOOP("ParameterTexts", "characteristic diffusion length (Eq. 13)"),
    QT_TRANSLATE_NOOP("ParameterTexts", "natural-convection coefficient on the belt (Eq. 14)"),
    QT_TRANSLATE_NOOP("ParameterTexts", "exposed area per kg of dry matter on the belt (Eq. 14)"),
    QT_TRANSLATE_NOOP("ParameterTexts", "mass fraction of the conveyor top layer (Eqs. 15-16)"),
    QT_TRANSLATE_NOOP("ParameterTexts", "flash-evaporation rate in the winnower (Eqs. 17-18)"),
    QT_TRANSLATE_NOOP("ParameterTexts", "heat loss of the winnower per kg of dry matter (Eq. 19)"),
    QT_TRANSLATE_NOOP("ParameterTexts", "residence time in the winnower (Eqs. 17-19)"),
    QT_TRANSLATE_NOOP("ParameterTexts", "residence time in the drying tube"),
    QT_TRANSLATE_NOOP("ParameterTexts", "transport time on the conveyor"),
    QT_TRANSLATE_NOOP("ParameterTexts", "time constant of the hot-air temperature actuator"),
    QT_TRANSLATE_NOOP("ParameterTexts",
                      "outlet mixing: first-order lag of X_out and T_out (belt and winnower holdup)"),
    QT_TRANSLATE_NOOP("ParameterTexts", "tube wall heat loss, its transfer units over the tube: T_gas = "
                                        "T_amb + (T_hot - T_amb) exp(-theta s / tau_HDT)"),
    QT_TRANSLATE_NOOP(
        "ParameterTexts",
        "gas-phase coupling: T_gas falls by theta L_v (X_in - X) m_dry / (c_air m_air) along the tube, and w "
        "rises by theta (X_in - X) m_dry / m_air"),
    QT_TRANSLATE_NOOP("ParameterTexts", "fouling: h = h_HDT (1 - theta t), t since the batch started"),
    QT_TRANSLATE_NOOP("ParameterTexts", "first-order lag of the outlet moisture meter"),
    QT_TRANSLATE_NOOP("ParameterTexts", "constant offset of the outlet moisture meter"),
    QT_TRANSLATE_NOOP("ParameterTexts", "conveyor transport time minus tau_conv"),
    QT_TRANSLATE_NOOP("ParameterTexts",
                      "falling-rate drying: Eq. 10 times 1 - theta (X_cr - X)/X_cr below X_cr = 0.25 kg/kg"),
    QT_TRANSLATE_NOOP("ParameterTexts", "re-absorption on the conveyor: dX/dt gains theta RH"),
    QT_TRANSLATE_NOOP("ParameterTexts",
                      "offset of the inlet moisture gauge: the line sees X_in measured minus it"),
    QT_TRANSLATE_NOOP(
        "ParameterTexts",
        "time constant of the hot-air sensor: the line sees T_hot + tau dT_hot/dt (its inverse lag)"),
    QT_TRANSLATE_NOOP("ParameterTexts",
                      "share of the inlet gauge's fast variation (about its 20 s zero-phase mean) that is "
                      "scatter, not moisture: the line sees X_in with that share removed"),
    QT_TRANSLATE_NOOP("ParameterTexts", "onset of the mechanism extensions since each batch's start (0: from "
                                        "the start; transport_delay_error always acts from the start)"),
    QT_TRANSLATE_NOOP("ParameterTexts", "paper App. A"),
    QT_TRANSLATE_NOOP("ParameterTexts", "paper App. A (bounds: sign kept, tenfold range)"),
    QT_TRANSLATE_NOOP("ParameterTexts",
                      "gives D_eff ≈ 1.7e-10 m²/s at 57 °C, the order reported for tobacco lamina"),
    QT_TRANSLATE_NOOP("ParameterTexts", "typical of leaf materials (20–40 kJ/mol)"),
    QT_TRANSLATE_NOOP("ParameterTexts", "heat of sorption of tobacco adds up to about a third near dryness"),
    QT_TRANSLATE_NOOP("ParameterTexts", "humid air halves the surface gradient at saturation"),
    QT_TRANSLATE_NOOP("ParameterTexts", "cut tobacco strands (lamina with air spaces)"),
    QT_TRANSLATE_NOOP("ParameterTexts", "cut width about 1 mm"),
    QT_TRANSLATE_NOOP("ParameterTexts", "cut tobacco strands of 1–3 cm"),
    QT_TRANSLATE_NOOP("ParameterTexts", "paper §IV.C calibrated value"),
    QT_TRANSLATE_NOOP("ParameterTexts", "recirculated hot air of a tobacco dryer is humid"),
    QT_TRANSLATE_NOOP("ParameterTexts", "atmospheric"),
    QT_TRANSLATE_NOOP("ParameterTexts", "0 °C, the reference of the 2501 kJ/kg in Eq. 4"),
    QT_TRANSLATE_NOOP("ParameterTexts", "loose single layer"),
    QT_TRANSLATE_NOOP("ParameterTexts", "gives about 1 % dry-basis loss of the top layer on a 60 s belt"),
    QT_TRANSLATE_NOOP("ParameterTexts", "natural convection of a horizontal layer"),
    QT_TRANSLATE_NOOP("ParameterTexts", "top layer of about 2 kg/m²"),
    QT_TRANSLATE_NOOP("ParameterTexts", "top third of the layer exchanges with the air"),
    QT_TRANSLATE_NOOP("ParameterTexts", "about 0.4 % wb flash loss at 35 K excess temperature"),
    QT_TRANSLATE_NOOP("ParameterTexts", "turbulent air, short contact"),
    QT_TRANSLATE_NOOP("ParameterTexts", "a few seconds"),
    QT_TRANSLATE_NOOP("ParameterTexts", "tube of about 70 m at 10 m/s particle speed"),
    QT_TRANSLATE_NOOP("ParameterTexts", "belt of 12 m at 0.2 m/s"),
    QT_TRANSLATE_NOOP("ParameterTexts",
                      "heat exchanger and duct lag; used when T_hot follows its setpoint (MPC)"),
    QT_TRANSLATE_NOOP("ParameterTexts",
                      "distributed line: axial mixing on the belt, the winnower's stirred volume"),
    QT_TRANSLATE_NOOP("ParameterTexts", "extension tube_wall_heat_loss"),
    QT_TRANSLATE_NOOP("ParameterTexts", "extension gas_phase_coupling"),
    QT_TRANSLATE_NOOP("ParameterTexts", "extension heat_transfer_fouling"),
    QT_TRANSLATE_NOOP("ParameterTexts", "extension moisture_meter_lag"),
    QT_TRANSLATE_NOOP("ParameterTexts", "extension moisture_meter_offset"),
    QT_TRANSLATE_NOOP("ParameterTexts", "extension transport_delay_error"),
    QT_TRANSLATE_NOOP("ParameterTexts", "extension falling_rate_drying"),
    QT_TRANSLATE_NOOP("ParameterTexts", "extension ambient_reabsorption"),
    QT_TRANSLATE_NOOP("ParameterTexts", "extension inlet_moisture_sensor_offset"),
    QT_TRANSLATE_NOOP("ParameterTexts", "extension hot_air_sensor_lag"),
    QT_TRANSLATE_NOOP("ParameterTexts", "extension inlet_moisture_sensor_noise"),
    QT_TRANSLATE_NOOP("ParameterTexts", "set by discovery for a cause that starts mid-batch"),
};

QString translated(std::string_view english) {
    const std::string text(english);
    return QCoreApplication::translate("ParameterTexts", text.c_str());
}

} // namespace

QString parameterMeaning(const properties::ParameterInfo& info) {
    return translated(info.meaning);
}

QString parameterSource(const properties::ParameterInfo& info) {
    // "extension heat_transfer_fouling": the cause by the name every tab gives it.
    const std::string_view source = info.source;
    constexpr std::string_view prefix = "extension ";
    if (source.substr(0, prefix.size()) == prefix) {
        return QCoreApplication::translate("ParameterTexts", "added for the cause: %1")
            .arg(causeDisplayName(std::string(source.substr(prefix.size()))));
    }
    return translated(info.source);
}

} // namespace drytwin::widgets
