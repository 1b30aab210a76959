#!/bin/sh
# session 26: the reduced column with and without a rolling resistance (fix nscd/polyhedra
# rolling_friction, in.column -var rolling_friction), mu_w 0.6, seeds 1001-7007, two runs
# at a time, from a git archive of commit 2e497b9, the binary of commit b774b66's code
# (the same core); that session's machine was 1.6-1.9x slower than session 25's.
postprocess/sweep.py rolling_friction 0 0.1 --seeds 1001 2002 3003 4004 5005 6006 7007 \
    --var mu_w 0.6 --deck input_scripts/in.column_reduced --out out --jobs 2
