#!/bin/sh
# warm_geometry on new seeds, with what the warm start changes step by step and two
# controls that change only rounding. The rule, written before the new seeds' runs
# finished: warm_geometry becomes the default if on seeds 20020-25025 no observable's
# paired shift exceeds 1.5 standard errors and H_n's stays below +1; otherwise it stays
# off (it stayed off). Run from the repository's top.
V="--var mu_w 0.6 --var t_relax 75 --var t_end 145 --var v_wall 0.1 --deck input_scripts/in.column_reduced"
# 0. per-step comparison (per_step_comparison.patch applied to the build of 8c19ea5, run with
#    WG_WARM_COMPARE=1): every warm query also made cold on the same poses, the warm answer
#    used; per_step_8008.txt, per_step_9009.txt (method codes 0 gjk, 3 gjk_far)
WG_WARM_COMPARE=1 postprocess/sweep.py warm_geometry yes --seeds 8008 9009 $V --jobs 2 --out cmp
# 1. new seeds, the two arms in two lanes of one run each (new_seeds.csv; seed 20020's warm
#    run is in ../warm_geometry_2026-11-28/new_seeds.csv)
postprocess/sweep.py warm_geometry no --seeds 20020 21021 22022 23023 24024 25025 $V --jobs 1 --out new_no &
postprocess/sweep.py warm_geometry yes --seeds 21021 22022 23023 24024 25025 $V --jobs 1 --out new_yes &
# 2. the rounding-only control (control.csv): a WIREGRAIN_NATIVE=ON build (-march=native,
#    FMA; the option of commit 622935e) of a tree from before warm_geometry (its deck has no
#    such variable), beside the two lanes above
postprocess/sweep.py ke_relax 1e-6 --seeds 8008 9009 10010 11011 12012 13013 $V --liggghts NATIVE_BUILD/liggghts --jobs 1 --out control &
wait
# 3. the cold build with a rounding-size noise that changes from call to call
#    (jitter.patch applied to a5dadca: gaps +-3e-17, normals +-3e-15 per component, on the
#    grain pairs' points and the touching segment-grain pairs), jitter.csv
WG_JITTER=3e-17 postprocess/sweep.py warm_geometry no --seeds 8008 10010 12012 14014 16016 18018 $V --jobs 1 --out jitter_a &
WG_JITTER=3e-17 postprocess/sweep.py warm_geometry no --seeds 9009 11011 13013 15015 17017 19019 $V --jobs 1 --out jitter_b &
wait
docs/column/runs/warm_geometry_rounding_2026-11-28/paired.py
