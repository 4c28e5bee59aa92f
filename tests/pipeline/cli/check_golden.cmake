# Golden-file test of one `medusa` command (GUDHI style): run it, check its exit code, and compare
# its standard output, standard error and output files byte for byte with reference files.
#   cmake -DCOMMAND=<words joined by |> -DEXPECT_CODE=<n> -DWORKDIR=<dir> -DTEST=<test name> -DGOLDEN_DIR=<dir>
#         [-DSTDOUT=<golden name>] [-DSTDERR=<golden name>] [-DFILES=<output>=<golden name>|...]
#         -DMEDUSA=<path of the medusa binary> -DSOURCE_DIR=<source tree> -P check_golden.cmake
# Standard error must be empty unless STDERR names its golden file.
#
# Normalisation (the only volatile parts of medusa's output; applied to the output before comparing,
# and to what scripts/update-golden stores):
#   - the path of the medusa binary (argv[0], shown in `Usage:` lines and in the recorded command
#     line) becomes `medusa`;
#   - the work folder becomes <WORK> (first: the build folder may lie inside the source tree);
#   - the source tree (input paths recorded in the store, named in error messages) becomes <SOURCE>;
#   - the value of the `software version:` line of `medusa info` becomes <VERSION>;
#   - the random run id (`run id:` of `medusa info`, the `# medusa run` line of a diagrams CSV, the
#     data-medusa-run attribute of a barcode SVG) becomes <RUN_ID>.
# Everything else, floating-point text included, must match to the byte.
#
# With the environment variable MEDUSA_UPDATE_GOLDEN=1 (scripts/update-golden), the normalised
# outputs are written to the golden files instead of compared; the exit code is still checked.
cmake_minimum_required(VERSION 3.18)
foreach(required COMMAND EXPECT_CODE WORKDIR TEST GOLDEN_DIR MEDUSA SOURCE_DIR)
  if(NOT DEFINED ${required})
    message(FATAL_ERROR "check_golden.cmake: -D${required}=... is missing")
  endif()
endforeach()
file(MAKE_DIRECTORY ${WORKDIR})
string(REPLACE "|" ";" COMMAND "${COMMAND}")
string(REPLACE "|" ";" FILES "${FILES}")
set(update OFF)
if("$ENV{MEDUSA_UPDATE_GOLDEN}" STREQUAL "1")
  set(update ON)
endif()

function(normalise text out)
  string(REPLACE "${MEDUSA}" "medusa" text "${text}")
  string(REPLACE "${WORKDIR}" "<WORK>" text "${text}")
  string(REPLACE "${SOURCE_DIR}" "<SOURCE>" text "${text}")
  string(REGEX REPLACE "(^|\n)software version: [^\n]*" "\\1software version: <VERSION>" text "${text}")
  string(REGEX REPLACE "(run id: |# medusa run |data-medusa-run=\")[0-9a-f]+" "\\1<RUN_ID>" text "${text}")
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

set(failures "")
# Compares (or, when updating, stores) the normalised `text` with golden file `name`.
function(check_text what text name)
  normalise("${text}" text)
  set(golden ${GOLDEN_DIR}/${name})
  if(update)
    file(WRITE ${golden} "${text}")
    message(STATUS "updated ${golden}")
    return()
  endif()
  # Named after the test as well: tests of one golden file (diagrams on 1 and 3 threads) run in
  # parallel in the same work folder.
  set(actual ${WORKDIR}/${name}.${TEST}.actual)
  file(WRITE ${actual} "${text}")
  if(NOT EXISTS ${golden})
    set(failures "${failures}${what}: golden file ${golden} is missing (actual output in ${actual})\n"
        PARENT_SCOPE)
    return()
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${golden} ${actual} RESULT_VARIABLE differ)
  if(differ)
    # The first differing lines, so that a failure can be read in the CTest log.
    execute_process(COMMAND diff -u ${golden} ${actual} OUTPUT_VARIABLE diff_text ERROR_QUIET)
    string(LENGTH "${diff_text}" length)
    if(length GREATER 3000)
      string(SUBSTRING "${diff_text}" 0 3000 diff_text)
      set(diff_text "${diff_text}\n[... diff cut]")
    endif()
    set(failures "${failures}${what} differs from ${golden} (actual output in ${actual}):\n${diff_text}\n"
        PARENT_SCOPE)
  else()
    file(REMOVE ${actual})
  endif()
endfunction()

# Output files of an earlier run of this test would hide a command that no longer writes them.
foreach(pair IN LISTS FILES)
  string(REGEX REPLACE "=.*" "" output "${pair}")
  file(REMOVE ${WORKDIR}/${output})
endforeach()

execute_process(COMMAND ${COMMAND} WORKING_DIRECTORY ${WORKDIR}
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT "${code}" STREQUAL "${EXPECT_CODE}")
  message(FATAL_ERROR "command: ${COMMAND}\nexit code ${code}, expected ${EXPECT_CODE}\n"
                      "stdout:\n${out}\nstderr:\n${err}")
endif()
if(STDOUT)
  check_text(stdout "${out}" ${STDOUT})
elseif(NOT out STREQUAL "" AND NOT IGNORE_STDOUT)
  set(failures "${failures}stdout is not empty:\n${out}\n")
endif()
if(STDERR)
  check_text(stderr "${err}" ${STDERR})
elseif(NOT err STREQUAL "")
  set(failures "${failures}stderr is not empty:\n${err}\n")
endif()
foreach(pair IN LISTS FILES)
  string(REGEX REPLACE "=.*" "" output "${pair}")
  string(REGEX REPLACE "^[^=]*=" "" name "${pair}")
  if(NOT EXISTS ${WORKDIR}/${output})
    set(failures "${failures}output file ${output} was not written\n")
    continue()
  endif()
  file(READ ${WORKDIR}/${output} text)
  check_text("output file ${output}" "${text}" ${name})
endforeach()
if(NOT failures STREQUAL "")
  # Printed unformatted (a FATAL_ERROR message would rewrap the diff).
  message("command: ${COMMAND}\n${failures}")
  message(FATAL_ERROR "output differs from the golden files")
endif()
