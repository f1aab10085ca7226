#!/bin/sh
# Drapes N sampled designs on the built-in bodies and counts how many pass the judge's
# physical checks (no reference drape to compare with), with the failures by reason.
#
#   garmentcode-drape/tools/drape_sample.sh N SEED OUT_DIR BODIES_DIR [GARMENTCODE]
#
# BODIES_DIR holds the body meshes as NAME.obj (the judge's inside test needs them; the
# reference's are in shared/reference/drape/bodies); GARMENTCODE is the CLI binary
# (default: garmentcode on the PATH). Needs python3 with numpy and scipy, and the judge
# `judge_drape.py` (JUDGE, default ../shared/tools/judge_drape.py). Drapes run one at a
# time with the release build of the drape_case example. BODY_NAMES (default mean_all)
# are the bodies the designs are drawn on (those with a body mesh). The summary is
# OUT_DIR/summary.txt.
set -eu
n=$1 seed=$2 out=$3 bodies=$4 cli=${5:-garmentcode}
judge=${JUDGE:-../shared/tools/judge_drape.py}
here=$(cd "$(dirname "$0")/../.." && pwd)
cargo build --release -q -p garmentcode-drape --example drape_case
drape=${CARGO_TARGET_DIR:-$here/target}/release/examples/drape_case
"$cli" sample --n "$n" --seed "$seed" --out "$out/designs" --bodies "${BODY_NAMES:-mean_all}"
mkdir -p "$out/drapes"
: > "$out/results.txt"
for dir in "$out"/designs/rand_*; do
    name=$(basename "$dir")
    body=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['body'])" "$dir/sample_info.json" 2>/dev/null || echo mean_all)
    body=${body%.yaml}
    drapedir="$out/drapes/$name"
    if "$drape" "$dir/${name}_specification.json" "$body" "$dir/body_measurements.yaml" "$drapedir" > "$drapedir.log" 2>&1; then
        verdict=$(python3 "$judge" --body "$bodies/$body.obj" "$drapedir" | head -n 1)
    else
        verdict="FAIL $name: drape: $(tail -n 1 "$drapedir.log")"
    fi
    echo "$verdict" | tee -a "$out/results.txt"
done
{
    echo "$(grep -c '^PASS' "$out/results.txt") of $(wc -l < "$out/results.txt") designs pass the physical checks"
    echo "failures by reason:"
    grep '^FAIL' "$out/results.txt" | sed 's/^FAIL [^:]*: //; s/ |.*//' | tr ';' '\n' | sed 's/^ *//; s/:.*//' | sort | uniq -c | sort -rn
} | tee "$out/summary.txt"
