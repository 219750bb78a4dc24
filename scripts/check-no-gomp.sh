#!/usr/bin/env bash
# Fails when a library or program under the given folders defines one of libgomp's symbols
# (GOMP_*): only libgomp itself may, or every OpenMP region of the process goes through ours.
# Static archives are read with `nm`, shared objects and programs with `nm -D` (what the dynamic
# linker sees).
set -euo pipefail
status=0
while IFS= read -r -d '' file; do
    case "$file" in
        *.a) symbols=$(nm --defined-only "$file" 2>/dev/null || true) ;;
        *) symbols=$(nm -D --defined-only "$file" 2>/dev/null || true) ;;  # not ELF: empty
    esac
    if grep -E ' GOMP_' <<<"$symbols"; then
        echo "check-no-gomp: $file defines libgomp's symbols" >&2
        status=1
    fi
done < <(find "$@" -type f \( -name '*.a' -o -name '*.so*' -o -perm -u+x \) -print0)
[[ $status -eq 0 ]] && echo "check-no-gomp: no GOMP_ definition under $*"
exit $status
