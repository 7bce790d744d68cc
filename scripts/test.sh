#!/usr/bin/env bash
# The test command: every GPU test runs on a real Vulkan device (lavapipe on a machine without a
# GPU) with the Khronos validation layer on; a missing device or layer fails the run.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
export DREAMSCENE_REQUIRE_VALIDATION=1
cargo test --all-targets
