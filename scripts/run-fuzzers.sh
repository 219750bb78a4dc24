#!/usr/bin/env bash
# Runs every fuzz target of the file readers (tests/fuzz/fuzz_targets.h) for SA_FUZZ_SECONDS
# (10) seconds each, SA_FUZZ_JOBS (the number of cores) at a time, under the address and
# undefined-behaviour sanitizers (build-sanitized.sh), starting from seeds the project's writers
# make. A crash, a sanitizer report, a leak, an allocation over 2 GB or an input taking over 25 s
# fails the run; the input is kept in build-asan/fuzz/artifacts/ (fix the reader, then add it to
# tests/fuzz/regressions/<target>/). Prints executions and time per target. CI's last phase
# (.ci/run; docs/measurements.md, "Reliability").
# The mutations follow libFuzzer's -seed=SA_FUZZ_SEED (1): from a fresh corpus a run explores the
# same inputs each time, so that CI checks what was fuzzed before it landed and does not fail on a
# discovery of its own; SA_FUZZ_SEED=0 draws a random seed (to search for new crashes).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build-sanitized.sh fuzz_targets
build=${SA_SANITIZER_BUILD:-build-asan}
seconds=${SA_FUZZ_SECONDS:-10}
jobs=${SA_FUZZ_JOBS:-$(nproc)}
seed=${SA_FUZZ_SEED:-1}
root=$(pwd)
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:detect_odr_violation=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
export LSAN_OPTIONS="suppressions=$root/tests/sanitizers/lsan.supp:print_suppressions=0"
export ASAN_SYMBOLIZER_PATH=${ASAN_SYMBOLIZER_PATH:-$(command -v llvm-symbolizer-14 || true)}
fuzz="$build/fuzz"
rm -rf "$fuzz/seeds" "$fuzz/logs"
mkdir -p "$fuzz/artifacts" "$fuzz/logs"
"$build/bin/fuzz_seeds" "$fuzz/seeds"
targets=$(ls "$fuzz/seeds")

run_one() {
    local name=$1
    mkdir -p "$fuzz/corpus/$name"
    if "$build/bin/fuzz_$name" -seed="$seed" -max_total_time="$seconds" -timeout=25 -rss_limit_mb=2048 \
        -print_final_stats=1 -artifact_prefix="$fuzz/artifacts/$name-" \
        "$fuzz/corpus/$name" "$fuzz/seeds/$name" > "$fuzz/logs/$name.log" 2>&1; then
        echo "$name ok"
    else
        echo "$name FAILED (see $fuzz/logs/$name.log)"
    fi
}
export -f run_one
export build fuzz seconds seed
start=$(date +%s)
printf '%s\n' $targets | xargs -P "$jobs" -I{} bash -c 'run_one {}' | sort > "$fuzz/status.txt"
elapsed=$(( $(date +%s) - start ))

printf '| target | result | executions | exec/s | seconds | corpus |\n|---|---|---:|---:|---:|---:|\n'
failed=0
for name in $targets; do
    log="$fuzz/logs/$name.log"
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
    rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
    time=$(sed -n 's/^Done [0-9]* runs in \([0-9]*\) second.*/\1/p' "$log" | tail -1)
    corpus=$(ls "$fuzz/corpus/$name" | wc -l)
    result=$(grep -q "^$name ok" "$fuzz/status.txt" && echo ok || echo FAILED)
    [[ $result == ok ]] || failed=1
    printf '| %s | %s | %s | %s | %s | %s |\n' "$name" "$result" "${runs:-?}" "${rate:-?}" \
        "${time:-?}" "$corpus"
done
echo "run-fuzzers: $(echo $targets | wc -w) targets, ${seconds} s each, $jobs at a time: ${elapsed} s"
if [[ $failed -ne 0 ]]; then
    echo "run-fuzzers: failures; inputs in $fuzz/artifacts/" >&2
    for name in $targets; do grep -q "^$name ok" "$fuzz/status.txt" || tail -30 "$fuzz/logs/$name.log" >&2; done
    exit 1
fi
