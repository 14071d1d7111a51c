# Every third-party library, found once, as Debian 12 ships it (PLATFORM-NOTES.md).
find_package(PkgConfig REQUIRED)
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(SUNDIALS REQUIRED)
find_package(NLopt REQUIRED)
pkg_check_modules(IPOPT REQUIRED IMPORTED_TARGET ipopt)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(CLI11 REQUIRED)
pkg_check_modules(FFTW3 REQUIRED IMPORTED_TARGET fftw3)
# MQTT client for the live link (engine/live/, issue #73): Mosquitto's C library, libmosquitto-dev.
pkg_check_modules(MOSQUITTO REQUIRED IMPORTED_TARGET libmosquitto)
find_package(Boost 1.74 REQUIRED)

# libcsv (Debian libcsv-dev) has neither a CMake config nor a pkg-config file.
find_path(LIBCSV_INCLUDE_DIR csv.h REQUIRED)
find_library(LIBCSV_LIBRARY csv REQUIRED)
add_library(libcsv::csv UNKNOWN IMPORTED)
set_target_properties(libcsv::csv PROPERTIES IMPORTED_LOCATION ${LIBCSV_LIBRARY}
                                             INTERFACE_INCLUDE_DIRECTORIES ${LIBCSV_INCLUDE_DIR})

if(DRYTWIN_WITH_TORCH)
  find_package(Torch REQUIRED)
endif()

find_package(Qt5 5.15 REQUIRED COMPONENTS Core Gui Widgets Test Svg OpenGL Concurrent PrintSupport LinguistTools)
# Versionless Qt:: targets and qt_ commands below, so that Qt 6 is a switch here (ARCHITECTURE.md).
set(QT_VERSION_MAJOR 5)
pkg_check_modules(QWT REQUIRED IMPORTED_TARGET Qt5Qwt6)

# VTK's MPI dependency must be found first (PLATFORM-NOTES.md).
find_package(MPI REQUIRED COMPONENTS C)
find_package(VTK REQUIRED COMPONENTS GUISupportQt RenderingOpenGL2 InteractionStyle
             RenderingFreeType FiltersSources FiltersGeneral RenderingAnnotation CommonCore)

if(DRYTWIN_BUILD_BENCH)
  find_package(benchmark REQUIRED)
endif()
