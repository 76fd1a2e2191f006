#!/usr/bin/env bash
# What the default no-op tracer costs: the course-scene render (the built-in demo scene when
# ../shared/data is absent) built with the fill's trace hooks and built without any
# (SCANTRACE_NO_TRACE_HOOKS), run alternately in one session; plus the cost of tracing one
# triangle of the scene. Also compares the machine code of the untraced render in both builds.
#
#   bash scripts/bench_tracer_overhead.sh [ROUNDS]     (default 7 rounds × 41 repetitions)
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=${1:-7}
bash scripts/build.sh >/dev/null
with=build/bench/bench_tracer_overhead
without=build/bench/bench_tracer_overhead_nohooks

# The untraced render as the compiler emitted it: render_untraced and every function instantiated
# for the no-op tracer (which of them the compiler inlines into which changes with the code, so
# all are listed, by name), with addresses removed (they differ between two binaries even when
# the code is the same).
code_of() {
  local listing
  listing=$(nm --defined-only "$1" | awk '$2 ~ /^[TtWw]$/ {print $3}' |
    paste -d'|' - <(nm --defined-only "$1" | awk '$2 ~ /^[TtWw]$/ {print $3}' | c++filt) |
    grep -E '\|(scantrace::bench::render_untraced\(|.*NoTracer)' | sort -t'|' -k2)
  [ -n "$listing" ] || { echo "no untraced render found in $1" >&2; return 1; }
  while IFS='|' read -r symbol name; do
    echo "== $name"
    objdump -d --no-show-raw-insn --disassemble="$symbol" "$1" |
      sed -n '/^[0-9a-f]* <.*>:$/,$p' | tail -n +2 | cut -f2- |
      sed -E 's/0x[0-9a-f]+//g; s/[0-9a-f]{4,}//g; s/<[^>]*>//g'
  done <<<"$listing"
}
# Into variables first: a failure inside a process substitution would not stop the script, and
# two empty listings would compare "identical" (it once printed "identical ... (0 instructions)").
code_with=$(code_of "$with")
code_without=$(code_of "$without")
if [ -z "$code_with" ] || [ -z "$code_without" ]; then
  echo "machine code of the untraced render: not found in a build; nothing compared" >&2
  exit 1
fi
if [ "$code_with" = "$code_without" ]; then
  echo "machine code of the untraced render: identical in both builds ($(grep -c '^==' <<<"$code_with") functions, $(grep -vc '^==' <<<"$code_with") instructions)"
else
  echo "machine code of the untraced render: DIFFERS between the builds" >&2
  exit 1
fi

results=$(mktemp)
trap 'rm -f "$results"' EXIT
for ((i = 1; i <= rounds; i++)); do
  printf '\rround %d of %d' "$i" "$rounds" >&2
  # Alternate which binary goes first, so that drifts of the machine (frequency, neighbours) do
  # not always favour the same one.
  if ((i % 2)); then
    "$without" --mode untraced 2>/dev/null | sed 's/^untraced/nohooks/' >>"$results"
    "$with" --mode all 2>/dev/null >>"$results"
  else
    "$with" --mode all 2>/dev/null >>"$results"
    "$without" --mode untraced 2>/dev/null | sed 's/^untraced/nohooks/' >>"$results"
  fi
done
echo >&2
python3 - "$results" <<'PY'
import statistics, sys
times = {}
for line in open(sys.argv[1]):
    mode, us = line.split()
    times.setdefault(mode, []).append(float(us))
med = {m: statistics.median(v) for m, v in times.items()}
print("| render of the scene | median of per-round medians (µs) | ratio to no hooks |")
print("|---|---:|---:|")
for mode, label in [("nohooks", "fill built without trace hooks"),
                    ("untraced", "default no-op tracer"),
                    ("one-triangle", "tracing one triangle (scanline level)")]:
    print(f"| {label} | {med[mode]:.0f} | {med[mode] / med['nohooks']:.3f} |")
PY
