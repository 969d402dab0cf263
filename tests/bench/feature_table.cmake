# scripts/feature-table.sh, run small (96x96, 1 frame, ROUNDS=1): it ends with exit 0 and prints both
# tables with every row (15 off: 5 cases by 3 renderers; 18 on: 6 features by 3 renderers), each off
# row saying met or missed. Never the timings, which depend on the machine and its load. About 35 s
# on 2 cores (45 runs), so the limit leaves room for a busy machine. Exit 77 (no GL context) skips.
if(TARGET 11_clustered AND TARGET 14_shadows AND TARGET 17_ssao AND TARGET 18_pbr_materials
   AND TARGET 19_image_based_light)
  add_test(NAME bench.feature_table
    COMMAND ${BASH} -c "out=$(ROUNDS=1 scripts/feature-table.sh \"$0\" 96x96 1); rc=$?; \
      [ $rc -eq 77 ] && exit 77; [ $rc -eq 0 ] || { echo \"FAIL: feature-table.sh exited $rc\"; exit 1; }; \
      awk -F ' [|] ' ' \
        /^Measured .* UTC on .* cores.*, at 96x96/ { head = 1 } \
        /^## What a feature costs when off$/ { t = 1; next } \
        /^## What a feature costs when on$/ { t = 2; next } \
        /^## / { t = 0 } \
        t && /^[|] [^-]/ && $1 != \"| case\" && $1 != \"| feature\" { \
          rows[t]++; seen[t $1 \" \" $2 \" \" (t == 1 ? $3 : \"\")]++; \
          if (t == 1 && $7 !~ /^(met|[*][*]missed[*][*]) [|]$/) { print \"FAIL: no met or missed: \" $0; bad = 1 } } \
        END { \
          split(\"deferred forward-plus forward\", r, \" \"); \
          n = split(\"14 `--shadows 0`:teapots,17 `--ssao off`:teapots,19 `--ibl off --ssao off`:teapots_probes,18:default,18:teapots\", a, \",\"); \
          for (i = 1; i <= n; i++) for (j = 1; j <= 3; j++) { \
            split(a[i], p, \":\"); k = \"1| \" p[1] \" \" r[j] \" \" p[2]; \
            if (seen[k] != 1) { print \"FAIL: the off table has \" (seen[k] + 0) \" rows \" k; bad = 1 } }; \
          n = split(\"shadows,SSAO,image-based light,material maps,metallic-roughness over Blinn-Phong,emissive\", b, \",\"); \
          for (i = 1; i <= n; i++) for (j = 1; j <= 3; j++) { \
            k = \"2| \" b[i] \" \" r[j] \" \"; \
            if (seen[k] != 1) { print \"FAIL: the on table has \" (seen[k] + 0) \" rows \" k; bad = 1 } } \
          if (rows[1] != 15 || rows[2] != 18) { print \"FAIL: \" rows[1] \" off rows, \" rows[2] \" on rows: want 15, 18\"; bad = 1 } \
          if (!head) { print \"FAIL: no header line with the date, machine and size\"; bad = 1 } \
          if (bad) exit 1; print \"ok: both tables, 15 and 18 rows\" }' <<<\"$out\" || { echo \"$out\"; exit 1; }"
      $<TARGET_FILE_DIR:11_clustered>
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(bench.feature_table PROPERTIES LABELS golden SKIP_RETURN_CODE 77 TIMEOUT 300)
endif()
