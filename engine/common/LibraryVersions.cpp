#include "common/LibraryVersions.h"

#include <CLI/Version.hpp>
#include <Eigen/Core>
#include <IpoptConfig.h>
#include <boost/version.hpp>
#include <csv.h>
#include <fftw3.h>
#include <nlohmann/json.hpp>
#include <nlopt.hpp>
#include <sundials/sundials_config.h>
#ifdef DRYTWIN_HAVE_TORCH
#include <torch/version.h>
#endif

namespace drytwin {

namespace {
#define DRYTWIN_STR2(x) #x
#define DRYTWIN_STR(x) DRYTWIN_STR2(x)
} // namespace

std::string dryTwinVersion() {
    return DRYTWIN_VERSION;
}

std::vector<std::pair<std::string, std::string>> engineLibraryVersions() {
    int major = 0;
    int minor = 0;
    int bugfix = 0;
    nlopt::version(major, minor, bugfix);
    std::vector<std::pair<std::string, std::string>> v{
        {"Eigen", DRYTWIN_STR(EIGEN_WORLD_VERSION) "." DRYTWIN_STR(EIGEN_MAJOR_VERSION) "." DRYTWIN_STR(
                      EIGEN_MINOR_VERSION)},
        {"SUNDIALS (CVODES)", SUNDIALS_VERSION},
        {"NLopt", std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(bugfix)},
        {"Ipopt", IPOPT_VERSION},
        {"Boost", BOOST_LIB_VERSION},
        {"FFTW", fftw_version},
        {"nlohmann/json", std::to_string(NLOHMANN_JSON_VERSION_MAJOR) + "." +
                              std::to_string(NLOHMANN_JSON_VERSION_MINOR) + "." +
                              std::to_string(NLOHMANN_JSON_VERSION_PATCH)},
        {"CLI11", CLI11_VERSION},
        {"libcsv",
         std::to_string(CSV_MAJOR) + "." + std::to_string(CSV_MINOR) + "." + std::to_string(CSV_RELEASE)},
    };
#ifdef DRYTWIN_HAVE_TORCH
    v.emplace_back("libtorch", TORCH_VERSION);
#endif
    return v;
}

} // namespace drytwin
