#!/usr/bin/env bash
# Builds the one clang-14 sanitizer build in build-fuzz: the library, glider_plan and the tests with
# AddressSanitizer + UndefinedBehaviorSanitizer (Debug with -O1, every report fatal), the library and the flags with
# the coverage hooks of libFuzzer (-fsanitize=fuzzer-no-link), and the fuzz targets of fuzz/ linked with libFuzzer. The tests run on it in
# scripts/run_sanitizers.sh, the fuzzers in scripts/run_fuzzers.sh. Usage: scripts/build_sanitized.sh
# The Python module (an ASan library cannot be loaded into an uninstrumented interpreter) and MPI (which also
# checks that the build without MPI stays as it is) are left out of this build.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/setup.sh"
build="$root/build-fuzz"
# line tables only: the reports name file:line, and a clean build compiles and links faster than with full -g (the
# Debug type's own flags, -g, are emptied: after -gline-tables-only they gave full debug information again). The
# tests' own files are compiled at -O0 as in every build (OMPL_GLIDER_TEST_CXX_FLAGS in tests/CMakeLists.txt; the
# library, glider_plan and the fuzzers stay at -O1). The coverage hooks of libFuzzer
# (-fsanitize=fuzzer-no-link) go to the code the fuzzers reach only, the library and the command line's flags
# (OMPL_GLIDER_BUILD_FUZZERS in CMakeLists.txt), not to the tests
flags="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -O1 -gline-tables-only"
CC=clang-14 CXX=clang++-14 cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG= -DOMPL_GLIDER_BUILD_TESTS=ON \
  -DOMPL_GLIDER_BUILD_BENCHMARKS=OFF -DOMPL_GLIDER_BUILD_FUZZERS=ON \
  -DOMPL_GLIDER_BUILD_PYTHON=OFF -DOMPL_GLIDER_WITH_MPI=OFF -DCMAKE_CXX_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined" \
  >/dev/null
cmake --build "$build" -j"$(nproc)"
