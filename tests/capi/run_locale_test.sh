#!/bin/sh
# Runs the locale test in de_DE.UTF-8, made with localedef in a scratch
# folder (LOCPATH), so that neither root nor a generated system locale is
# needed.  The test itself reports 77 (skipped) if the locale still cannot
# be set.
#   run_locale_test.sh PATH/TO/capi_locale_test
set -u
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
if localedef -c -i de_DE -f UTF-8 "$scratch/de_DE.UTF-8" >/dev/null 2>&1; then
    LOCPATH=$scratch
    export LOCPATH
fi
"$1" de_DE.UTF-8
