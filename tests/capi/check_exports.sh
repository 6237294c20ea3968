#!/bin/sh
# libtriangle.so exports its C interface and nothing else, under a SONAME
# Debian gives Triangle's library, so that programs linked against that one
# find this one.
#   check_exports.sh PATH/TO/libtriangle.so
set -eu
lib=$1
soname=$(objdump -p "$lib" | awk '$1 == "SONAME" { print $2 }')
if [ "$soname" != "libtriangle-1.6.so" ]; then
    echo "SONAME is '$soname', not libtriangle-1.6.so (Debian's)"
    exit 1
fi
exported=$(nm -D --defined-only "$lib" | awk '$2 ~ /^[TDBRVW]$/ { print $3 }' | sort | tr '\n' ' ')
if [ "$exported" != "gpdr_last_error gpdr_triangulate_ex triangulate trifree " ]; then
    echo "exported: $exported"
    exit 1
fi
echo "libtriangle.so: SONAME $soname, exports $exported"
