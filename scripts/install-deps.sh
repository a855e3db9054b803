#!/usr/bin/env bash
# Installs the Debian 12 packages hecal builds and tests with (docs/build.md).
# Idempotent: prints nothing and touches nothing when every package is present.
# Usage: scripts/install-deps.sh [--sanitizers] [--browser]   (--sanitizers adds clang's
# AddressSanitizer, UndefinedBehaviorSanitizer and libFuzzer runtimes, libclang-rt-14-dev, for the
# sanitized robustness run of scripts/test.sh and the fuzzers; --browser adds Debian's chromium
# for the HTML report's browser test, tests/report/)
#
# The compiler is clang (Debian's clang-14), which the scripts use for a new build folder: it
# compiles hecal in about half the time GCC 12 takes (docs/build.md#build-time); GCC builds it too.
#
# The HTML report (docs/report.md): Plotly.js and the browser test's driver come from npm, pinned
# by web/package-lock.json; `npm ci` installs them into web/node_modules when it is missing (the
# build embeds web/node_modules/plotly.js-dist-min/plotly.min.js; configuring fails without it).
#
# Python (docs/python.md#install): the module builds for Debian's /usr/bin/python3, whose NumPy,
# pybind11, pytest and OpenCV (cv2) come from apt (/usr/lib/python3/dist-packages). When the
# `python3` first on PATH is another interpreter of the same major.minor (pyenv, a python.org
# build; not a venv of Debian's python, which can use --system-site-packages), this script also
# writes hecal-debian.pth into that interpreter's site-packages, naming two directories:
# /usr/lib/python3/dist-packages (Debian's packages) and the site directory where
# `cmake --install build --component python` puts hecal with the default prefix /usr/local
# (/usr/local/lib/python3.X/dist-packages). Then `python3 -c "import hecal"` works with either
# interpreter. Both are appended to sys.path, after the interpreter's own packages. Another
# major.minor cannot load the module (a different ABI) and is left alone.
set -euo pipefail

packages=(
  build-essential clang cmake ninja-build lld git pkg-config
  libeigen3-dev libceres-dev
  libopencv-dev libopencv-contrib-dev libapriltag-dev
  libyaml-cpp-dev libtinyxml2-dev nlohmann-json3-dev libcli11-dev
  libgtest-dev libgmock-dev libbenchmark-dev libglpk-dev
  python3-dev pybind11-dev python3-numpy python3-pytest python3-opencv
  nodejs
)
for flag in "$@"; do
  case "$flag" in
    --sanitizers) packages+=(libclang-rt-14-dev) ;;
    --browser) packages+=(chromium) ;;
    *) echo "install-deps: unknown flag $flag (fix: --sanitizers, --browser)" >&2; exit 2 ;;
  esac
done
# Debian's nodejs comes without npm (NodeSource's includes it).
command -v npm >/dev/null || packages+=(npm)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done
if [[ $(id -u) -ne 0 ]]; then
  sudo=sudo
else
  sudo=
fi
if [[ ${#missing[@]} -gt 0 ]]; then
  export DEBIAN_FRONTEND=noninteractive
  echo "install-deps: installing ${missing[*]}" >&2
  # A fresh machine may have no package lists yet: update once, then install.
  if ! $sudo apt-get install -y -q --no-install-recommends "${missing[@]}" >/dev/null; then
    $sudo apt-get update -q >/dev/null
    $sudo apt-get install -y -q --no-install-recommends "${missing[@]}" >/dev/null
  fi
fi

# The python3 on PATH, when it is not Debian's: hecal-debian.pth (see the header).
link_python() {
  local python debian
  python=$(command -v python3 || true)
  debian=/usr/bin/python3
  [[ -n "$python" && -x "$debian" ]] || return 0
  local query='import os, sys, sysconfig; print(os.path.realpath(sys.executable), "%d.%d" % sys.version_info[:2], sysconfig.get_path("purelib"), sysconfig.get_path("platlib"))'
  local exe version site _ debian_exe debian_version _p debian_platlib
  read -r exe version site _ < <("$python" -c "$query") || return 0
  read -r debian_exe debian_version _p debian_platlib < <("$debian" -c "$query") || return 0
  [[ "$exe" != "$debian_exe" && "$version" == "$debian_version" ]] || return 0
  local pth="$site/hecal-debian.pth"
  local want
  want=$(printf '%s\n%s\n' /usr/lib/python3/dist-packages "$debian_platlib")
  [[ -f "$pth" && "$(cat "$pth")" == "$want" ]] && return 0
  local writer=
  [[ -w "$site" ]] || writer=$sudo
  echo "install-deps: $python ($version) is not Debian's python3: writing $pth" >&2
  printf '%s\n' "$want" | $writer tee "$pth" >/dev/null
}
link_python

# The HTML report's npm packages (see the header).
web="$(cd "$(dirname "$0")/.." && pwd)/web"
if [[ ! -d "$web/node_modules" ]]; then
  echo "install-deps: npm ci in $web" >&2
  (cd "$web" && npm ci --no-audit --no-fund >/dev/null)
fi
