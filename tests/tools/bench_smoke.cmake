# grass-measure bench --quick as a smoke run (ctest bench_smoke): the reduced football field from
# the player camera on GL at 160 x 90, twice with one reference cache. The first run renders
# the truths (the supersampled references of two seeds) and the reference's timed frame; the
# second finds all three in the cache. Both write a CSV with every preset's error normalised by
# the seed-to-seed error at three scales.
#   cmake -DMEASURE=<grass-measure> -DOUT=<dir> -P bench_smoke.cmake
file(REMOVE_RECURSE "${OUT}")
set(failures 0)
foreach(run first second)
  execute_process(
    COMMAND ${MEASURE} bench --quick --backend gl --size 160x90 --frames 1 --out ${OUT}/${run}
            --references ${OUT}/references
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${run} run: exit ${rc}\n${out}${err}")
  endif()
  set(${run}_log "${err}")
  file(READ "${OUT}/${run}/bench.csv" csv)
  set(${run}_csv "${csv}")
endforeach()

# The first run rendered both truths and the timed reference, the second read them.
if(NOT first_log MATCHES "truth A rendered" OR NOT first_log MATCHES "truth B rendered")
  message(SEND_ERROR "the first run did not render the truths:\n${first_log}")
endif()
if(NOT second_log MATCHES "truth A from the cache" OR NOT second_log MATCHES "truth B from the cache"
   OR second_log MATCHES "rendered at")
  message(SEND_ERROR "the second run did not take the truths from the cache:\n${second_log}")
endif()
# One reference row and four presets, each with normalised errors at x1, x2, x4 that are
# numbers, the same in both runs (the images are deterministic, the reference comes from the
# cache the second time).
foreach(run first second)
  string(REGEX MATCHALL "\nfootball,player,gl,[a-z]+,[^\n]+" rows "${${run}_csv}")
  list(LENGTH rows n)
  if(NOT n EQUAL 5)
    message(SEND_ERROR "${run} run: ${n} football player rows in bench.csv, expected 5:\n${${run}_csv}")
  endif()
  set(${run}_errors "")
  foreach(row IN LISTS rows)
    string(REPLACE "," ";" cells "${row}")
    # norm_ssim_error_x1 .. norm_rms_x4: columns 38 .. 43 (0-based 37 .. 42)
    list(SUBLIST cells 37 6 norm)
    foreach(v IN LISTS norm)
      if(NOT v MATCHES "^[0-9]+\\.[0-9]+$")
        message(SEND_ERROR "${run} run: a normalised error is not a number: ${v} in\n${row}")
      endif()
    endforeach()
    list(APPEND ${run}_errors "${norm}")
  endforeach()
endforeach()
if(NOT first_errors STREQUAL second_errors)
  message(SEND_ERROR "the normalised errors differ between the runs:\n${first_errors}\n${second_errors}")
endif()
# reference_cached (column 25): the reference's timed frame came from the cache the second time only.
foreach(run first second)
  string(REGEX MATCH "\nfootball,player,gl,reference,[^\n]+" row "${${run}_csv}")
  string(REPLACE "," ";" cells "${row}")
  list(GET cells 24 cached)
  set(${run}_cached ${cached})
endforeach()
if(NOT first_cached STREQUAL "0" OR NOT second_cached STREQUAL "1")
  message(SEND_ERROR "reference_cached: ${first_cached} and ${second_cached}, expected 0 and 1")
endif()
