#!/usr/bin/env bash
# Builds scantrace and runs its demo: the embedded default, no input needed.
#   bash scripts/demo.sh [-o DIR]      (default DIR: ./scantrace-demo)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

# Only the command and its libraries are built, with only the packages they need (the tests,
# examples and benchmarks come with scripts/test.sh). Build output, with its [ NN%] progress,
# goes to stderr so that the demo's own output stands out.
bash "$root/scripts/build.sh" --demo >&2
# Run from the caller's directory, so that a relative -o DIR means what the caller meant.
exec "$root/build/cli/scantrace" demo "$@"
