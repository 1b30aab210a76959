#!/bin/sh
# Which half of warm_geometry moves H_n? fix nscd/polyhedra's (grain pairs) and fix
# wire/grain's (segment-grain pairs) warm starts run apart, on seeds 8008-19019, which have
# cold runs (../early_end_paired_2026-11-27, ../warm_geometry_2026-11-28) and runs with
# both warm (../warm_geometry_2026-11-28). split.patch (applied to a snapshot of the
# repository at commit 8af8a67 in snap/, not in the tree): in.column's variable
# warm_segments (default: warm_geometry) sets fix wire/grain's keyword alone.
# Rule, written before the runs: this study changes no default. It reports each arm's
# paired shifts against the cold runs; an arm is "consistent with no shift" when no
# observable's paired shift exceeds 2 standard errors of the difference and H_n's stays
# below +1.
V="--var mu_w 0.6 --var t_relax 75 --var t_end 145 --var v_wall 0.1 --deck snap/input_scripts/in.column_reduced --liggghts ./liggghts --jobs 1"
S="8008 9009 10010 11011 12012 13013 14014 15015 16016 17017 18018 19019"
snap/postprocess/sweep.py warm_segments yes --var warm_geometry no --seeds $S $V --out segments > segments.log 2>&1 &
snap/postprocess/sweep.py warm_segments no --var warm_geometry yes --seeds $S $V --out grains > grains.log 2>&1 &
wait
docs/column/runs/warm_split_2026-12-04/paired.py > docs/column/runs/warm_split_2026-12-04/paired.txt
