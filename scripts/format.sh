#!/usr/bin/env bash
# Formats C++ files with the repository's .clang-format (100 columns).
#   scripts/format.sh FILE...          rewrite the files in place
#   scripts/format.sh --check FILE...  list the files that would change; exit 1 if any would
#   scripts/format.sh --all [--check]  every .cpp/.hpp under packages/, apps/ and tests/
# Needs clang-format (Debian: clang-format).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
check=0 all=0 files=()
for a in "$@"; do
  case "$a" in
    --check) check=1 ;;
    --all) all=1 ;;
    -h|--help) sed -n '2,6p' "$0"; exit 0 ;;
    *) files+=("$a") ;;
  esac
done
if [ "$all" -eq 1 ]; then
  mapfile -t files < <(cd "$root" && git ls-files 'packages/*.cpp' 'packages/*.hpp' 'apps/*.cpp' \
                         'apps/*.hpp' 'tests/*.cpp' 'tests/*.hpp' | sed "s|^|$root/|")
fi
if [ ${#files[@]} -eq 0 ]; then
  echo "format.sh: no files given (see --help)" >&2
  exit 2
fi
command -v clang-format >/dev/null || { echo "format.sh: clang-format is not installed" >&2; exit 2; }
style=--style=file  # the .clang-format at the repository root
if [ "$check" -eq 1 ]; then
  # One clang-format process for all files (one per file costs ~40 ms each); its diagnostics
  # ("FILE:LINE:COL: error: code should be clang-formatted") name the files that would change.
  if out=$(clang-format "$style" --dry-run -Werror "${files[@]}" 2>&1); then
    exit 0
  fi
  printf '%s\n' "$out" | sed -n 's/^\(.*\):[0-9]*:[0-9]*: error: .*/\1/p' | sort -u
  exit 1
fi
clang-format "$style" -i "${files[@]}"
