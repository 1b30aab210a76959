#!/bin/sh
# A silo to compare with (docs/results.md, "A silo to compare with"): input_scripts/in.silo
# at its defaults (D = 9, 130 grains in 10 layers of 13, mu_wall 0.5, mu_p 0.5), seeds
# 1001 2002 3003, at rest (the floor stays) and with the floor lowered by 0.05 a_max at 0.02
# after each layer (the wall friction mobilized); one run at a time, one core each.
# Run from the repository root; each run's post/silo.txt and its in.silo lines are kept here.
set -e
R=$(pwd)
D=docs/column/runs/silo_2026-12-06
W=${WORK:-/tmp/silo_study}
for mode in rest mobilized; do
  for seed in 1001 2002 3003; do
    mkdir -p $W/$mode/seed$seed
    extra=""; [ $mode = mobilized ] && extra="-var v_floor 0.02"
    (cd $W/$mode/seed$seed && $R/build/liggghts -in $R/input_scripts/in.silo -var root $R -var seed $seed \
        -var mu_wall 0.5 $extra > out.txt)
    mkdir -p $D/$mode/seed$seed
    cp $W/$mode/seed$seed/post/silo.txt $D/$mode/seed$seed/
    grep "^in.silo" $W/$mode/seed$seed/out.txt > $D/$mode/seed$seed/final.txt
  done
done
/usr/bin/python3 postprocess/janssen.py $D/rest/seed* $D/mobilized/seed* --plot docs/figures/silo_janssen.png > $D/janssen.txt
