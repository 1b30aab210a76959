#!/bin/sh
# Session 32: warm_geometry again, after session 31's +2.75 SE of H_n over 12 seeds.
# The rule, written down before the runs below finished: warm_geometry becomes the default
# if on the new seeds 20020-25025 (which session 31's question did not see) no observable's
# paired shift exceeds 1.5 standard errors and H_n's stays below +1 (session 31's
# direction not repeated); otherwise it stays off.
V="--var mu_w 0.6 --var t_relax 75 --var t_end 145 --var v_wall 0.1 --deck input_scripts/in.column_reduced"
# 0. per-step comparison (per_step_comparison.patch applied to the build of 8c19ea5, run with
#    WG_WARM_COMPARE=1): every warm query also made cold on the same poses, the warm answer
#    used; per_step_8008.txt, per_step_9009.txt (method codes 0 gjk, 3 gjk_far)
WG_WARM_COMPARE=1 postprocess/sweep.py warm_geometry yes --seeds 8008 9009 $V --jobs 2 --out cmp
# 1. new seeds, the two arms in two lanes of one run each (new_seeds.csv)
postprocess/sweep.py warm_geometry no --seeds 20020 21021 22022 23023 24024 25025 $V --jobs 1 --out new_no &
postprocess/sweep.py warm_geometry yes --seeds 21021 22022 23023 24024 25025 $V --jobs 1 --out new_yes &
# 2. the rounding-only control (control.csv): session 30's WIREGRAIN_NATIVE=ON build, with
#    session 30's tree (its deck has no warm_geometry), beside the two lanes above
postprocess/sweep.py ke_relax 1e-6 --seeds 8008 9009 10010 11011 12012 13013 $V --liggghts NATIVE_BUILD/liggghts --jobs 1 --out control &
wait
# 3. the cold build with a rounding-size noise that changes from call to call
#    (jitter.patch applied to a5dadca: gaps +-3e-17, normals +-3e-15 per component, on the
#    grain pairs' points and the touching segment-grain pairs), jitter.csv
WG_JITTER=3e-17 postprocess/sweep.py warm_geometry no --seeds 8008 10010 12012 14014 16016 18018 $V --jobs 1 --out jitter_a &
WG_JITTER=3e-17 postprocess/sweep.py warm_geometry no --seeds 9009 11011 13013 15015 17017 19019 $V --jobs 1 --out jitter_b &
wait
