#!/bin/sh
# The reduced column's wire laid three ways (docs/results.md, "One continuous wire"): the
# paper's separate double loops, one wire of double loops (continuous) and one wire of flat
# spirals (spiral, pitch 0.7: a layer's spiral from R/4 to R = 3 is 190 beads long, the double
# loop 189), seeds 4242, 1001, 2002, 3003, 5005, 6006, one core per run; the build and decks
# of commit 54600ba. Run from the repository root; summary.csv is the table of the final lines.
for seed in 4242 1001 2002 3003 5005 6006; do for layout in loops continuous spiral; do
  d=runs/${layout}_s$seed; mkdir -p $d
  (cd $d && ../../build/liggghts -in ../../input_scripts/in.column_reduced -var root ../.. \
      -var seed $seed -var wire_layout $layout -var spiral_pitch 0.7 > out.txt && grep "in.column final" out.txt)
done; done
