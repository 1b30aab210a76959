#!/bin/sh
# The reduced column laid as one continuous wire against the paper's separate double loops
# (docs/results.md, "One continuous wire"): seeds 4242, 1001, 2002, one core per run.
# Run from the repository root.
for layout in loops continuous; do for seed in 4242 1001 2002; do
  d=runs/${layout}_s$seed; mkdir -p $d
  (cd $d && ../../build/liggghts -in ../../input_scripts/in.column_reduced -var root ../.. \
      -var seed $seed -var wire_layout $layout > out.txt && grep "in.column final" out.txt)
done; done
