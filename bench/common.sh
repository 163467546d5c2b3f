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

bench_require_segslam() {  # sets segslam
  segslam="$build/segslam"
  [[ -x "$segslam" ]] || bench_fail "$segslam not built (run ./setup.sh)"
}

bench_require_dir() {  # a folder the bench reads, from ../shared
  [[ -d "$1" ]] || bench_fail "$1 not found (set SEGSLAM_SHARED_DIR)"
}
