#!/usr/bin/env bash
# Install what is missing, build, and run the whole test suite.
#   scripts/test.sh              the test suite (Release build)
#   scripts/test.sh --sanitize   then the same suite again under ASan + UBSan (CMakePresets.json)
# CI (CI=true) always adds the sanitizer pass: it fits well within CI's time.
set -euo pipefail
cd "$(dirname "$0")/.."
sanitize=0
[ "${1:-}" = "--sanitize" ] && sanitize=1
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
