#!/usr/bin/env bash
# Runs tests/export_engine.rs (three.js, glTF validator, gltf-transform, recast-navigation,
# splat-transform, Blender) on each prompt below, and prints the engine glb's export time and size
# against the plain one-node glb of the same scene.ply. From the repository root:
#   bash scripts/engine_export_prompts.sh
set -uo pipefail
prompts=(
  "a cozy living room" "a small bedroom" "a rustic kitchen" "a kid's bedroom"
  "a Japanese zen garden" "a small cafe terrace" "a tavern" "a classroom for 24 students"
  "a home office with two desks and a bookshelf" "a dining room with a table and six chairs"
  "a studio apartment with a sofa, a bed and a tv" "a hotel lobby with armchairs and a reception desk"
)
bin=target/release/dreamscene
work=$(mktemp -d)
printf '%-50s %8s %9s %8s %9s %s\n' prompt plain_s plain_MB engine_s engine_MB tests
for p in "${prompts[@]}"; do
  d="$work/scene"; rm -rf "$d"
  "$bin" generate "$p" --draft --renders 0 --out "$d" >/dev/null 2>&1 || { echo "$p: generate failed"; continue; }
  t0=$(date +%s.%N); "$bin" export "$d/scene.ply" --format glb --out "$work/plain.glb" >/dev/null; t1=$(date +%s.%N)
  "$bin" export "$d" --format glb --out "$work/engine.glb" >/dev/null; t2=$(date +%s.%N)
  r=$(DREAMSCENE_ENGINE_PROMPT="$p" cargo test --release -q --test export_engine 2>&1 | grep -E "^test result" | sed 's/test result: //; s/;.*//')
  printf '%-50s %8.2f %9.1f %8.2f %9.1f %s\n' "$p" "$(echo "$t1 - $t0" | bc)" \
    "$(echo "$(stat -c %s "$work/plain.glb") / 1000000" | bc -l)" "$(echo "$t2 - $t1" | bc)" \
    "$(echo "$(stat -c %s "$work/engine.glb") / 1000000" | bc -l)" "$r"
done
rm -rf "$work"
