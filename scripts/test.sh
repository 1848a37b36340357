#!/usr/bin/env bash
# Install what is missing, build, and run the whole test suite.
#   scripts/test.sh              the test suite (Release build)
#   scripts/test.sh --sanitize   then the same suite again under ASan + UBSan (CMakePresets.json;
#                                the thesis' experiments, the longest physics runs and the longest
#                                command-line scripts run in the Release pass only)
#   scripts/test.sh --long       also the long experiments (full built-in runs, minutes each)
# CI (CI=true) always adds the sanitizer pass: it fits well within CI's time.
set -euo pipefail
cd "$(dirname "$0")/.."
sanitize=0
for arg in "$@"; do
  case "$arg" in
    --sanitize) sanitize=1 ;;
    --long) export TALUS_LONG_TESTS=1 ;;
    *) echo "scripts/test.sh: unknown option '$arg' (allowed: --sanitize, --long)" >&2; exit 2 ;;
  esac
done
[ "${CI:-}" = "true" ] && sanitize=1
scripts/install-deps.sh
scripts/build.sh
ctest --test-dir build --output-on-failure --parallel "$(nproc)"
if [ "$sanitize" = 1 ]; then
  echo "== the test suite under AddressSanitizer + UndefinedBehaviorSanitizer =="
  cmake --preset sanitize > /dev/null
  cmake --build --preset sanitize --parallel "$(nproc)"
  ctest --preset sanitize --parallel "$(nproc)"
fi
