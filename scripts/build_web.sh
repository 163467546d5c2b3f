#!/usr/bin/env bash
# Builds the `segslam view` front end: installs the pinned npm packages (web/package-lock.json:
# three.js, esbuild, playwright-core for the browser test) and bundles web/src into web/dist.
# Needs node and npm (scripts/install_deps.sh); without them it says so and builds nothing, and
# `segslam view` then asks for this script to be run.
set -euo pipefail
cd "$(dirname "$0")/../web"
if ! command -v npm >/dev/null 2>&1; then
  echo "[web] npm not found: the viewer front end is not built (install nodejs and npm)" >&2
  exit 0
fi
# npm ci reinstalls from scratch; skip it while node_modules matches the lockfile.
if [ ! -f node_modules/.package-lock.json ] || ! cmp -s package-lock.json node_modules/.segslam-lock; then
  npm ci --no-audit --no-fund --loglevel=error
  cp package-lock.json node_modules/.segslam-lock
fi
npm run --silent build
