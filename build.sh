#!/usr/bin/env bash
# One entry point for setting up, building, testing and running the examples.
#
#   ./build.sh example   install what is missing, build, run the main example
#   ./build.sh test      install what is missing, build, run every test (ctest)
#   ./build.sh deps      only install the Debian packages (needs root or sudo)
#   ./build.sh build     only configure and build build/liggghts and the tests
#
# Environment: BUILD_DIR (default ./build), JOBS (default: number of cores),
# LIGGGHTS_SOURCE_DIR (a LIGGGHTS-PUBLIC 3.8.0 checkout instead of Debian's source
# package), CTEST_ARGS (extra ctest arguments, e.g. "-L core").
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
cd "$here"
BUILD_DIR="${BUILD_DIR:-$here/build}"
JOBS="${JOBS:-$(nproc)}"

# Debian 12 packages the build, the tests and the post-processing need.
# Never Debian's binary 'liggghts': it recommends ParaView, which conflicts with libvtk9-dev.
PACKAGES=(
  build-essential cmake ccache patch dpkg-dev pkg-config
  openmpi-bin libopenmpi-dev
  libeigen3-dev libcgal-dev libgsl-dev libvtk9-dev libboost-dev
  libgtest-dev libgmock-dev
  libfclib-dev libsiconos-numerics-dev
  python3 python3-numpy python3-scipy python3-matplotlib python3-vtk9  # scipy: postprocess/janssen.py
  xvfb  # postprocess/render_column.py: Debian's VTK renders through X only, Xvfb without a display
  slurmctld slurmd slurm-client munge  # tests/regression/test_slurm.py: a one-node Slurm for sweep.py --scheduler slurm
)

as_root() {
  if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi
}

# A deb-src twin of the configured Debian main archive, so that
# 'apt-get source --download-only liggghts' can fetch the upstream tarball.
ensure_deb_src() {
  if apt-cache showsrc liggghts 2>/dev/null | grep -q '^Package: liggghts'; then
    return 0
  fi
  local out=/etc/apt/sources.list.d/wiregrain-deb-src.sources
  echo "build.sh: adding a deb-src entry ($out) for Debian's liggghts source package"
  local tmp
  tmp="$(mktemp)"
  # deb822 stanzas of type deb → same stanza as deb-src
  for f in /etc/apt/sources.list.d/*.sources; do
    [ -f "$f" ] || continue
    [ "$f" = "$out" ] && continue
    awk 'BEGIN{RS=""; ORS="\n\n"}
         /(^|\n)Types:[^\n]*(^| )deb( |\n|$)/ && /(^|\n)Components:[^\n]* main/ && !/security/ {
           gsub(/Types:[^\n]*/, "Types: deb-src"); print }' "$f" >> "$tmp"
  done
  # one-line format
  if [ -f /etc/apt/sources.list ]; then
    grep -E '^deb [^#]* main' /etc/apt/sources.list | grep -v security | sed 's/^deb /deb-src /' \
      > "$tmp.list" || true
    if [ -s "$tmp.list" ]; then
      as_root install -m 644 "$tmp.list" /etc/apt/sources.list.d/wiregrain-deb-src.list
    fi
  fi
  if [ -s "$tmp" ]; then
    as_root install -m 644 "$tmp" "$out"
  fi
  rm -f "$tmp" "$tmp.list"
  as_root apt-get update -q
}

install_deps() {
  local missing=()
  for p in "${PACKAGES[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
      missing+=("$p")
    fi
  done
  if [ "${#missing[@]}" -gt 0 ]; then
    echo "build.sh: installing ${missing[*]}"
    as_root apt-get update -q
    DEBIAN_FRONTEND=noninteractive as_root apt-get install -y -q --no-install-recommends "${missing[@]}"
  fi
  local tarball="${HOME}/.cache/wiregrain/liggghts_3.8.0+repack1.orig.tar.xz"
  if [ -z "${LIGGGHTS_SOURCE_DIR:-}" ] && [ ! -f "$tarball" ]; then
    ensure_deb_src
  fi
}

configure_and_build() {
  local args=(-S "$here" -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release)
  if [ -n "${LIGGGHTS_SOURCE_DIR:-}" ]; then
    args+=("-DLIGGGHTS_SOURCE_DIR=$LIGGGHTS_SOURCE_DIR")
  fi
  if [ -n "${WIREGRAIN_NATIVE:-}" ]; then
    args+=("-DWIREGRAIN_NATIVE=$WIREGRAIN_NATIVE")
  fi
  cmake "${args[@]}"
  cmake --build "$BUILD_DIR" -j "$JOBS"
}

run_tests() {
  # ctest schedules the 2-rank tests (PROCESSORS 2) so that the cores are not oversubscribed
  # shellcheck disable=SC2086
  ctest --test-dir "$BUILD_DIR" --output-on-failure -j "$JOBS" ${CTEST_ARGS:-}
}

# The main example; see docs/examples.md.
run_example() {
  local work="$BUILD_DIR/examples/column"
  mkdir -p "$work"
  cp "$here/examples/column/in.column_small" "$work/"
  echo "build.sh: running examples/column (the reduced wire-reinforced column, 2 MPI ranks) in $work"
  (cd "$work" && OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
     mpirun --oversubscribe -np 2 "$BUILD_DIR/liggghts" -in in.column_small -var root "$here")
  echo "build.sh: output in $work (log.liggghts, column.obs, post/grains.vtp.series and post/wire.vtp.series for ParaView)"
}

case "${1:-}" in
  deps) install_deps ;;
  build) install_deps; configure_and_build ;;
  test) install_deps; configure_and_build; run_tests ;;
  example) install_deps; configure_and_build; run_example ;;
  *)
    sed -n '2,13p' "$0"
    exit 2
    ;;
esac
