# Golden-file tests of the `medusa` CLI (labels `cli` and `golden`): each command is run on small
# real inputs and its stdout, stderr and output files are compared byte for byte with the reference
# files of tests/data/cli/golden (README.txt there says how each was verified; scripts/update-golden
# rewrites them). The stores are written once by the fixture tests golden_run_*.
set(GOLDEN_CHECK ${CMAKE_CURRENT_SOURCE_DIR}/check_golden.cmake)
set(GOLDEN_DIR ${PROJECT_SOURCE_DIR}/tests/data/cli/golden)
set(GOLDEN_WORK ${CMAKE_CURRENT_BINARY_DIR}/golden)

# medusa_golden_test(<name> ARGS <medusa arguments...> [CODE <exit code, default 0>]
#                    [STDOUT <golden>] [STDERR <golden>] [FILES <output>=<golden>...]
#                    [SETUP <fixture>] [REQUIRES <fixtures...>] [IGNORE_STDOUT])
# Without STDOUT, stdout must be empty, unless IGNORE_STDOUT (a run whose summary names its own
# output files, checked elsewhere).
function(medusa_golden_test name)
  cmake_parse_arguments(G "IGNORE_STDOUT" "CODE;STDOUT;STDERR;SETUP" "ARGS;FILES;REQUIRES" ${ARGN})
  if(NOT DEFINED G_CODE)
    set(G_CODE 0)
  endif()
  # Words are joined with `|` (a CMake list would split the -D argument).
  set(command "$<TARGET_FILE:medusa>")
  foreach(word IN LISTS G_ARGS)
    string(APPEND command "|${word}")
  endforeach()
  string(REPLACE ";" "|" files "${G_FILES}")
  add_test(NAME golden_${name}
           COMMAND ${CMAKE_COMMAND} "-DCOMMAND=${command}" -DEXPECT_CODE=${G_CODE} -DWORKDIR=${GOLDEN_WORK} -DTEST=${name}
                   -DGOLDEN_DIR=${GOLDEN_DIR} -DSTDOUT=${G_STDOUT} -DSTDERR=${G_STDERR} "-DFILES=${files}"
                   -DMEDUSA=$<TARGET_FILE:medusa> -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -DIGNORE_STDOUT=${G_IGNORE_STDOUT}
                   -P ${GOLDEN_CHECK})
  set_tests_properties(golden_${name} PROPERTIES LABELS "cli;golden")
  if(G_SETUP)
    set_tests_properties(golden_${name} PROPERTIES FIXTURES_SETUP ${G_SETUP})
  endif()
  if(G_REQUIRES)
    set_tests_properties(golden_${name} PROPERTIES FIXTURES_REQUIRED "${G_REQUIRES}")
  endif()
endfunction()

# The stores: the first 3 frames of examples/sorting_3d, of the non-sorting control and of the second
# sorting seed (tests/data/cli/README.txt), radius 3. The run writes the CSV of all diagrams too.
medusa_golden_test(run_small ARGS run --force ${DATA}/cells_3frames.csv.gz -o small.h5 --radius 3 --quiet
                   STDOUT run_small.txt FILES small.diagrams.csv=run_small.diagrams.csv SETUP golden_small_store)
# The store side runs on the engine's thread with --threads 1 and on a thread of its own otherwise
# (AsyncObserver): both give the same diagrams.
foreach(threads 1 2)
  medusa_golden_test(run_small_on_${threads}_threads ARGS run --force ${DATA}/cells_3frames.csv.gz -o small_${threads}_threads.h5
                     --radius 3 --quiet --threads ${threads} FILES small_${threads}_threads.diagrams.csv=run_small.diagrams.csv
                     IGNORE_STDOUT)
endforeach()
foreach(run nosorting_3d sorting_3d_seed2)
  medusa_golden_test(run_${run} ARGS run --force ${DATA}/${run}_3frames.csv.gz -o ${run}_3frames.h5 --radius 3 --quiet
                     STDOUT run_${run}.txt SETUP golden_compare_stores)
endforeach()

set(small REQUIRES golden_small_store)
medusa_golden_test(info ARGS info small.h5 STDOUT info.txt ${small})
medusa_golden_test(diagrams_all ARGS diagrams small.h5 STDOUT diagrams_all.txt ${small})
# The thread count does not change the diagrams: one and three threads give the same golden text.
foreach(threads 1 3)
  medusa_golden_test(diagrams_all_on_${threads}_threads ARGS diagrams small.h5 --threads ${threads}
                     STDOUT diagrams_all.txt ${small})
endforeach()
medusa_golden_test(diagrams_forward_h0 ARGS diagrams small.h5 --filtration forward --dim 0
                   STDOUT diagrams_forward_h0.txt ${small})
medusa_golden_test(diagrams_reverse_h2 ARGS diagrams small.h5 --filtration reverse --dim 2
                   STDOUT diagrams_reverse_h2.txt ${small})
medusa_golden_test(diagrams_type2 ARGS diagrams small.h5 --type 2 STDOUT diagrams_type2.txt ${small})
# A type by its name (as `medusa info` lists it) is the type of that id.
medusa_golden_test(diagrams_type_by_name ARGS diagrams small.h5 --type NonCondensing STDOUT diagrams_type2.txt
                   ${small})
medusa_golden_test(diagrams_type1_h0_zero_length ARGS diagrams small.h5 --type 1 --dim 0 --zero-length
                   STDOUT diagrams_type1_h0_zero_length.txt ${small})
medusa_golden_test(barcode_pers ARGS barcode small.h5 --format pers STDOUT barcode_all.pers ${small})
medusa_golden_test(barcode_csv ARGS barcode small.h5 --format csv STDOUT barcode_all.csv ${small})
medusa_golden_test(barcode_json_type2 ARGS barcode small.h5 --format json --type 2 STDOUT barcode_type2.json
                   ${small})
medusa_golden_test(barcode_svg_h2 ARGS barcode small.h5 --format svg --dim 2 -o barcode_h2.svg
                   FILES barcode_h2.svg=barcode_h2.svg ${small})
medusa_golden_test(curves_frames ARGS curves small.h5 --frames-only -o curves STDOUT curves_frames.txt
                   FILES curves.curves.csv=curves_frames.csv curves.curves.svg=curves_frames.svg
                         curves.sorting.csv=curves_frames_sorting.csv
                         curves.sorting.svg=curves_frames_sorting.svg ${small})
medusa_golden_test(at_csv ARGS at small.h5 --time 100 -o at_100.csv STDOUT at_100.txt FILES at_100.csv=at_100.csv
                   ${small})
medusa_golden_test(at_vtk_type1 ARGS at small.h5 --time 50.5 --type 1 -o at_type1_50.5.vtk
                   STDOUT at_type1_50.5.txt FILES at_type1_50.5.vtk=at_type1_50.5.vtk ${small})

set(stores small.h5 nosorting_3d_3frames.h5 sorting_3d_seed2_3frames.h5)
set(compared REQUIRES golden_small_store golden_compare_stores)
medusa_golden_test(compare_h0 ARGS compare ${stores} --type all --dim 0 --essential -o compare_h0 STDOUT compare_h0.txt
                   FILES compare_h0.distances.csv=compare_h0.distances.csv
                         compare_h0.heatmap.svg=compare_h0.heatmap.svg
                         compare_h0.dendrogram.svg=compare_h0.dendrogram.svg ${compared})
medusa_golden_test(compare_type1_h1_finite
                   ARGS compare ${stores} --type 1 --dim 1 --ignore-essential -o compare_type1_h1
                   STDOUT compare_type1_h1.txt
                   FILES compare_type1_h1.distances.csv=compare_type1_h1.distances.csv
                         compare_type1_h1.heatmap.svg=compare_type1_h1.heatmap.svg
                         compare_type1_h1.dendrogram.svg=compare_type1_h1.dendrogram.svg ${compared})

# The ten longest type-1 classes with their cells (stored by the run); checked by check_classes_oracle.py.
medusa_golden_test(classes_type1_top10 ARGS classes small.h5 --type 1 --top 10 STDOUT classes_type1_top10.txt
                   ${small})

medusa_golden_test(help ARGS --help STDOUT help.txt)
# `medusa` alone prints the same help, exit 0.
medusa_golden_test(no_subcommand STDOUT help.txt)
foreach(sub run info diagrams barcode compare curves at classes report sweep)
  medusa_golden_test(${sub}_help ARGS ${sub} --help STDOUT help_${sub}.txt)
endforeach()

# Errors: one line on stderr and the exit code of the README (2 command line, 3 input, 5 store).
medusa_golden_test(error_unknown_option ARGS run --no-such-option CODE 2 STDERR error_unknown_option.txt)
medusa_golden_test(error_missing_input ARGS run --force ${DATA}/no_such_run.csv.gz -o missing.h5 --radius 3
                   CODE 3 STDERR error_missing_input.txt)
medusa_golden_test(error_malformed_input ARGS run --force ${DATA}/malformed.csv -o malformed.h5 --radius 3
                   CODE 3 STDERR error_malformed_input.txt)
medusa_golden_test(error_missing_store ARGS info no_such_store.h5 CODE 5 STDERR error_missing_store.txt)
medusa_golden_test(error_dim_out_of_range ARGS diagrams small.h5 --dim 7 CODE 2
                   STDERR error_dim_out_of_range.txt ${small})
medusa_golden_test(error_unknown_type ARGS diagrams small.h5 --type 9 CODE 3 STDERR error_unknown_type.txt
                   ${small})
medusa_golden_test(error_unknown_type_name ARGS diagrams small.h5 --type Medium CODE 3
                   STDERR error_unknown_type_name.txt ${small})
medusa_golden_test(error_time_outside_run ARGS at small.h5 --time 250 -o late.csv CODE 3
                   STDERR error_time_outside_run.txt ${small})
medusa_golden_test(error_compare_one_store ARGS compare small.h5 CODE 2 STDERR error_compare_one_store.txt
                   ${small})

# The golden files against each other and against GUDHI (pers reader, bottleneck distance).
add_test(NAME golden_files_agree_with_each_other_and_with_gudhi
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/verify_golden.py ${GOLDEN_DIR}
                 $<TARGET_FILE:medusa> ${GOLDEN_WORK})
set_tests_properties(golden_files_agree_with_each_other_and_with_gudhi PROPERTIES LABELS "cli;golden"
                     FIXTURES_REQUIRED "golden_small_store;golden_compare_stores")
