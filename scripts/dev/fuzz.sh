#!/usr/bin/env bash
# Builds every cargo-fuzz target under tests/fuzz and runs them all in parallel for SECONDS each,
# starting from the seed files in tests/fuzz/seeds/<target>/; prints each target's executions and
# whether it found anything (crashes land in tests/fuzz/artifacts/<target>/).
#
#   scripts/dev/fuzz.sh 600          # ten minutes each
#   FUZZ_NICE=0 scripts/dev/fuzz.sh 60
#
# Needs a nightly toolchain, or a stable one with RUSTC_BOOTSTRAP=1 (set here when no nightly is
# installed). Uses cargo-fuzz (`cargo install cargo-fuzz`) when it is installed; without it the
# targets are built with the same instrumentation flags by plain cargo and run directly.
set -euo pipefail
secs=${1:?usage: scripts/dev/fuzz.sh SECONDS}
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root"
fuzz_dir=tests/fuzz
nice_level=${FUZZ_NICE:-19}
if rustup toolchain list 2>/dev/null | grep -q '^nightly'; then
    cargo=(cargo +nightly)
else
    export RUSTC_BOOTSTRAP=1
    cargo=(cargo)
fi
target_dir=${CARGO_TARGET_DIR:-$root/target}/fuzz
triple=$(rustc -vV | sed -n 's/^host: //p')
if "${cargo[@]}" fuzz --version >/dev/null 2>&1; then
    have_fuzz=1
    "${cargo[@]}" fuzz build --fuzz-dir "$fuzz_dir" --target-dir "$target_dir" -O
    targets=$("${cargo[@]}" fuzz list --fuzz-dir "$fuzz_dir")
else
    # cargo-fuzz's own flags (sanitizer none): coverage counters, comparison tracing, cfg fuzzing.
    have_fuzz=0
    RUSTFLAGS="-Cpasses=sancov-module -Cllvm-args=-sanitizer-coverage-level=4 \
-Cllvm-args=-sanitizer-coverage-inline-8bit-counters -Cllvm-args=-sanitizer-coverage-pc-table \
-Cllvm-args=-sanitizer-coverage-trace-compares --cfg fuzzing -Cdebug-assertions -Coverflow-checks" \
        "${cargo[@]}" build --release --manifest-path "$fuzz_dir/Cargo.toml" --target "$triple" \
        --target-dir "$target_dir" --bins
    targets=$(sed -n 's/^name = "\(.*\)"$/\1/p' "$fuzz_dir/Cargo.toml" | grep -v '^dreamscene-fuzz$')
fi
logs=$(mktemp -d /tmp/dreamscene-fuzz.XXXXXX)
for t in $targets; do
    corpus=$fuzz_dir/corpus/$t
    mkdir -p "$corpus"
    cp -n "$fuzz_dir/seeds/$t/"* "$corpus/" 2>/dev/null || true
    (
        set +e
        # -rss_limit_mb / -malloc_limit_mb: an allocation sized by an untrusted header is a finding.
        limits=(-max_total_time="$secs" -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=1024)
        if [ "$have_fuzz" = 1 ]; then
            nice -n "$nice_level" "${cargo[@]}" fuzz run --fuzz-dir "$fuzz_dir" \
                --target-dir "$target_dir" -O "$t" "$corpus" -- "${limits[@]}" >"$logs/$t.log" 2>&1
        else
            mkdir -p "$fuzz_dir/artifacts/$t"
            nice -n "$nice_level" "$target_dir/$triple/release/$t" "$corpus" "${limits[@]}" \
                -artifact_prefix="$fuzz_dir/artifacts/$t/" >"$logs/$t.log" 2>&1
        fi
        echo $? >"$logs/$t.rc"
    ) &
done
wait
status=0
for t in $targets; do
    rc=$(cat "$logs/$t.rc")
    runs=$(grep -o 'Done [0-9]* runs' "$logs/$t.log" | tail -1 || true)
    if [ "$rc" = 0 ]; then
        echo "$t: ${runs:-no summary} in ${secs} s, no finding"
    else
        echo "$t: FAILED (exit $rc), see $logs/$t.log and $fuzz_dir/artifacts/$t/"
        status=1
    fi
done
exit $status
