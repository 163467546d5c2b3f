# Sourced by the bench scripts: where the project, its build and ../shared are, and the checks
# and option handling every script shares. Messages name the script that failed.
bench_name="$(basename "$0")"
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$root/build"
shared="${SEGSLAM_SHARED_DIR:-$root/../shared}"

bench_fail() {  # message
  echo "$bench_name: $1" >&2
  exit 1
}

bench_unknown_option() {  # option
  echo "$bench_name: unknown option '$1'" >&2
  exit 2
}

# For a script whose only options are --build DIR and --out DIR (sets build and out).
bench_parse_build_out() {
  while [[ $# -gt 0 ]]; do
    case "$1" in
      --build) build="$2"; shift 2 ;;
      --out) out="$2"; shift 2 ;;
      *) bench_unknown_option "$1" ;;
    esac
  done
}

# For a script whose options are --build DIR, --out DIR, --runs N and --only NAME[,NAME...]
# (sets build, out, runs and only; set out and runs to the script's defaults first).
bench_parse_runs_only() {
  only=""
  while [[ $# -gt 0 ]]; do
    case "$1" in
      --build) build="$2"; shift 2 ;;
      --out) out="$2"; shift 2 ;;
      --runs) runs="$2"; shift 2 ;;
      --only) only="$2"; shift 2 ;;
      *) bench_unknown_option "$1" ;;
    esac
  done
}

bench_require_segslam() {  # sets segslam
  segslam="$build/segslam"
  [[ -x "$segslam" ]] || bench_fail "$segslam not built (run ./setup.sh)"
}

bench_require_dir() {  # a folder the bench reads, from ../shared
  [[ -d "$1" ]] || bench_fail "$1 not found (set SEGSLAM_SHARED_DIR)"
}

# Makes a dev-suite composite once into SUITE/NAME (../shared/tools/composite.py --jpeg 95 with
# OPTIONS): on tum_fr1_xyz_300, or for FRAMES 898 on three sweeps of it (SUITE/long_base).
bench_make_composite() {  # suite name frames options
  local suite=$1 name=$2 frames=$3 options=$4
  [[ -f "$suite/$name/mask.txt" ]] && return
  local base_options=()
  if [[ "$frames" == 898 ]]; then
    [[ -f "$suite/long_base/rgb.txt" ]] ||
      /usr/bin/python3 "$shared/tools/long_base.py" "$shared/data/tum_fr1_xyz_300" \
        "$suite/long_base" --passes 3 > "$suite/long_base.log"
    base_options=(--base "$suite/long_base")
  fi
  echo "$bench_name: making $name"
  # shellcheck disable=SC2086
  /usr/bin/python3 "$shared/tools/composite.py" "${base_options[@]}" --out "$suite/$name" \
    --jpeg 95 $options > "$suite/$name.log" 2>&1 ||
    bench_fail "composite.py failed for $name (see $suite/$name.log)"
}
