#!/usr/bin/env bash
# Mutation testing with Stryker.NET (the dotnet-stryker tool of .config/dotnet-tools.json), one area at a time.
# Usage: tests/mutation/run.sh AREA [extra dotnet-stryker options]   AREA: kuka | parser | release | geometry | bridge | ur | kukaxml
# Each area has its own configuration (tests/mutation/AREA.json): the files it mutates, the tests that may kill the mutants
# (a test-case filter; never the convention tests, which fail under Stryker's instrumentation), net10.0 only, one test
# process at a time. Reports go to StrykerOutput/AREA/ (not committed): reports/mutation-report.html and .json.
# Not part of dotnet test or .ci/run: a run takes minutes to tens of minutes.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
area="${1:-}"
config="$root/tests/mutation/$area.json"
if [[ -z "$area" || ! -f "$config" ]]; then
  echo "usage: tests/mutation/run.sh AREA [dotnet-stryker options]; areas:" \
    "$(cd "$root/tests/mutation" && ls ./*.json | sed 's|^\./||; s|\.json$||' | tr '\n' ' ')" >&2
  exit 2
fi
shift
cd "$root"
dotnet tool restore >/dev/null
cd "$root/tests/Machina.Tests"
exec dotnet tool run dotnet-stryker --config-file "$config" --output "$root/StrykerOutput/$area" --skip-version-check "$@"
