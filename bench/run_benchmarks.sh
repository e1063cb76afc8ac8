#!/usr/bin/env bash
# Runs the benchmark suite and prints a table (Google Benchmark's console table, counters as columns).
# Usage: bench/run_benchmarks.sh [BUILD_DIR] [extra google-benchmark flags, e.g. --benchmark_filter=iccg]
set -euo pipefail
build=${1:-build}
shift || true
exec "$build/mistfall_bench" --benchmark_counters_tabular=true "$@"
