# Sourced by run.sh and test.sh: configures a build directory the same way for both, so that
# test.sh after run.sh only builds what run.sh left out.
# configure_build DIR [cmake arguments...]: a new directory gets Ninja when it is installed (it
# keeps both cores busy across targets and writes each file's compile time to .ninja_log,
# docs/build-speed.md); an existing directory keeps the generator it was made with.
configure_build() {
  local dir=$1
  shift
  local generator=()
  if [ ! -f "$dir/CMakeCache.txt" ] && command -v ninja >/dev/null 2>&1; then
    generator=(-G Ninja)
  fi
  cmake -S . -B "$dir" "${generator[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo "$@"
}
