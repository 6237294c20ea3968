#!/usr/bin/env bash
# Triangles produced by each Steiner point placement (issue 5; the GPDR
# paper's Table 1): quality meshes with no area bound at minimum angles of
# 10, 20 and 30 degrees, on the project's flow and pipe models.
#
#   scripts/bench-quality.sh [MODEL.poly ...]     default: poly-samples/flow.poly pipe.poly
#   TRIANGLE=/tmp/triangle/triangle scripts/bench-quality.sh
#   ANGLES="10 20 25" scripts/bench-quality.sh
#
# Prints a Markdown table shaped like the paper's Table 1: one row per
# placement (gpdr -P0 circumcentre, -P1 off-centre, -P2 the paper's
# optimisation), plus Triangle 1.6 (off-centres) when TRIANGLE names a binary;
# one column per angle and model.  The paper's own figures (its models, which
# ours only resemble) follow for reference.
set -euo pipefail
source "$(dirname "$0")/bench-common.sh"
root=$(cd "$(dirname "$0")/.." && pwd)
models=("$@")
((${#models[@]})) || models=("$root/poly-samples/flow.poly" "$root/poly-samples/pipe.poly")
read -r -a angles <<<"${ANGLES:-10 20 30}"
work="$BENCH_DIR/quality"
mkdir -p "$work"

# triangles PROGRAM SWITCHES MODEL: the triangle count of one quiet run, or
# "failed" (its last message goes to stderr).
triangles() {
  local program=$1 switches=$2 model=$3 log="$work/run.log"
  local input
  input="$work/$(basename "$model")"
  cp -f "$model" "$input"
  if ( cd "$work" && "$program" "-Q$switches" "$(basename "$input")" >"$log" 2>&1 ); then
    ele_count "${input%.poly}.1.ele"
  else
    echo "bench-quality: $(basename "$program") -$switches $(basename "$model"): $(tail -1 "$log")" >&2
    echo failed
  fi
}

header="| placement |"
rule="|---|"
for a in "${angles[@]}"; do
  for m in "${models[@]}"; do
    header+=" $(basename "${m%.poly}") q$a |"
    rule+="---:|"
  done
done

row() {
  local label=$1 program=$2 extra=$3 line
  line="| $label |"
  for a in "${angles[@]}"; do
    for m in "${models[@]}"; do
      line+=" $(triangles "$program" "pq$a$extra" "$m") |"
    done
  done
  echo "$line"
}

echo "$header"
echo "$rule"
row "gpdr -P0 circumcentre" "$GPDR" P0
row "gpdr -P1 off-centre" "$GPDR" P1
row "gpdr -P2 optimisation" "$GPDR" P2
if [ -n "${TRIANGLE:-}" ]; then
  row "Triangle 1.6 (off-centre)" "$TRIANGLE" ""
fi

cat <<'EOF'

The paper's Table 1 (its flow and pipe models, meshed with Triangle 1.6 and
the placements built on it), for reference:

| placement | flow q10 | pipe q10 | flow q20 | pipe q20 | flow q30 | pipe q30 |
|---|---:|---:|---:|---:|---:|---:|
| circumcentre | 2173 | 3033 | 3153 | 4651 | 8758 | 10655 |
| off-centre | 1906 | 2941 | 2942 | 4411 | 6175 | 8585 |
| optimisation | 1805 | 2841 | 2932 | 4359 | 6319 | 8581 |
EOF
