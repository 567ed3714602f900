# bounce-bench's command line refuses what it cannot measure before rendering anything:
# each case must exit 2 (bad input) with one line naming the option, and leave no report
# folder behind. A shell wrapper checks the status, since ctest alone can only tell zero
# from non-zero.
if(TARGET bounce-bench)
  set(cases
      "accumulate_zero|--accumulate|--accumulate 0"
      "accumulate_huge|--accumulate|--accumulate 100000"
      "reference_budget_zero|--reference-budget|--reference-budget 0"
      "reference_budget_negative|--reference-budget|--reference-budget -5"
      "reference_budget_nan|--reference-budget|--reference-budget nan"
      "reference_spp_one|--reference-spp|--reference-spp 1"
      "scene_missing|does-not-exist.gltf|--scene ${PROJECT_SOURCE_DIR}/content/does-not-exist.gltf"
      "scene_directory|not a regular file|--scene ${PROJECT_SOURCE_DIR}/content"
      "technique_unknown|NoSuchGI|--techniques NoSuchGI")
  foreach(case ${cases})
    string(REPLACE "|" ";" parts "${case}")
    list(GET parts 0 name)
    list(GET parts 1 must_say)
    list(GET parts 2 arguments)
    add_test(NAME bench_cli.${name}
             COMMAND sh -c "dir=${CMAKE_CURRENT_BINARY_DIR}/bench-cli-${name}; rm -rf $dir; \
out=$($<TARGET_FILE:bounce-bench> --width 8 --height 8 --out $dir ${arguments} 2>&1); s=$?; \
echo \"$out\"; [ $s -eq 2 ] && printf '%s' \"$out\" | grep -qF -- '${must_say}' && [ ! -e $dir ]")
    set_tests_properties(bench_cli.${name} PROPERTIES
      ENVIRONMENT "BOUNCE_ROOT=${PROJECT_SOURCE_DIR};BOUNCE_SHADER_CACHE=${PROJECT_BINARY_DIR}/shader-cache"
      WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} LABELS bench-cli TIMEOUT 120)
  endforeach()
endif()

# The other benchmark programs: bad values exit 2 with one line naming the option (not
# CLI11's own codes, 105 for an out-of-range value; NaN passed its range checks), and an
# unwritable --json is an error, not a silent exit 0.
set(other_cases
    "render_bench_light_move_nan|bounce-render-bench|--light-move|--light-move nan"
    "render_bench_sizes_zero|bounce-render-bench|--sizes|--sizes 0"
    "ray_bench_rays_zero|bounce-ray-bench|--rays|--rays 0"
    "ray_bench_json_unwritable|bounce-ray-bench|--json|--rays 256 --runs 1 --json /proc/nope.json")
foreach(case ${other_cases})
  string(REPLACE "|" ";" parts "${case}")
  list(GET parts 0 name)
  list(GET parts 1 program)
  list(GET parts 2 must_say)
  list(GET parts 3 arguments)
  if(TARGET ${program})
    add_test(NAME bench_cli.${name}
             COMMAND sh -c "out=$($<TARGET_FILE:${program}> ${arguments} 2>&1); s=$?; echo \"$out\"; \
[ $s -eq 2 ] && printf '%s' \"$out\" | grep -F -- '${must_say}' | grep -q '^${program}: '")
    set_tests_properties(bench_cli.${name} PROPERTIES
      ENVIRONMENT "BOUNCE_ROOT=${PROJECT_SOURCE_DIR};BOUNCE_SHADER_CACHE=${PROJECT_BINARY_DIR}/shader-cache"
      WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} LABELS bench-cli TIMEOUT 300)
  endif()
endforeach()
