#!/usr/bin/env bash
# Installs every Debian 12 package DryTwin needs to build, test and run.
# Safe to run twice: apt-get install is idempotent. Uses sudo only when not root.
set -euo pipefail

PACKAGES=(
  build-essential cmake pkg-config git
  # a faster build on two cores: Ninja's scheduling and lld's link (docs/build-speed.md)
  ninja-build lld
  # Qt 5.15 (Qwt and VTK's Qt module exist for Qt 5 only on Debian 12)
  qtbase5-dev qttools5-dev qttools5-dev-tools libqt5svg5-dev libqt5opengl5-dev
  # Qt's own translations (qtbase_zh_CN.qm: file dialogs, message-box buttons in Chinese)
  qttranslations5-l10n
  libqwt-qt5-dev
  # numerics
  libeigen3-dev libsundials-dev libnlopt-cxx-dev coinor-libipopt-dev libtorch-dev
  # libtorch's matrix products go to whichever libblas.so.3 is installed; without this it is the
  # reference BLAS, and the LSTM's sgemm was 43 % of `drytwin evaluate` on the demo (10.2 s; 4.7 s
  # with OpenBLAS). The threaded build, set to one thread per caller at start
  # (engine/common/BlasThreads.h): DryTwin calls BLAS from two threads at once (a training
  # session's MPC beside a Train job), which the serial build is not safe for (it crashed inside
  # Ipopt; test_baselines trainsBesideIpoptSolvesOnAnotherThread).
  libopenblas0-pthread
  # 3D view
  libvtk9-dev libvtk9-qt-dev
  # well-kept helpers instead of hand-written code:
  #   JSON, CLI parsing, CSV parsing, FFT, statistics (Boost.Math distributions)
  nlohmann-json3-dev libcli11-dev libcsv-dev libfftw3-dev libboost-dev
  # the live link to a running line (drytwin live, generate --publish; docs/live.md): Mosquitto's
  # C client library, and the broker and its command-line clients for the live tests and a demo line
  libmosquitto-dev mosquitto mosquitto-clients
  # tests and benchmarks
  libbenchmark-dev
  # screenshots of the GUI and headless GUI tests; a CJK font for the Chinese interface
  xvfb xauth fonts-wqy-zenhei
)

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  SUDO="sudo"
fi

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages already installed"
  exit 0
fi

echo "install-deps: installing ${#missing[@]} packages: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
