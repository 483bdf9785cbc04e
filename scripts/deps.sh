#!/usr/bin/env bash
# Installs the Debian packages trirast needs, when they are missing. Idempotent; silent when
# everything is already there. Uses apt-get as root, or through sudo.
set -euo pipefail

PACKAGES=(
  cmake g++ make pkg-config               # build
  clang libclang-rt-14-dev                # libFuzzer target (scripts/fuzz.sh): clang++, its runtimes
  libgtest-dev libbenchmark-dev           # GoogleTest, Google Benchmark
  libsystemc-dev                          # SystemC 2.3.4 (transaction-level model)
  verilator iverilog                      # RTL simulation
  yosys nextpnr-ice40 fpga-icestorm       # synthesis, place and route
  z3 boolector cvc5                       # SMT solvers of the formal proofs (yosys-smtbmc)
  gtkwave                                 # waveform viewer (traces)
  xvfb xauth imagemagick                  # GTKWave headless in tests/gtkwave (xvfb-run), screenshots
  libglm-dev libassimp-dev assimp-testmodels  # mesh scenes and camera
  libpng-dev                              # PNG images
  libcli11-dev                            # CLI11: command-line options and --help
  nlohmann-json3-dev                      # JSON: reports, the sweep's result files
  python3-matplotlib                      # plots (scripts call /usr/bin/python3)
  slurm-wlm munge parallel                # distributed sweep: local Slurm (scripts/slurm_local.sh), GNU parallel
)

missing=()
for p in "${PACKAGES[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

echo "deps.sh: installing ${missing[*]}" >&2
if [[ $(id -u) -eq 0 ]]; then
  SUDO=()
elif command -v sudo >/dev/null 2>&1; then
  SUDO=(sudo)
else
  echo "deps.sh: need root or sudo to install: ${missing[*]}" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${SUDO[@]}" apt-get update -qq >/dev/null
"${SUDO[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "deps.sh: done" >&2
