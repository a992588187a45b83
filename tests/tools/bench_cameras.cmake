# grass-measure bench at a game camera (ctest bench_topdown): the reduced hills from top-down
# (100 m up, 85 degrees down), DEFAULT on GL at 96 x 54, the truths supersampled x2. The
# camera's name parses, the frame is measured, the part of the field is in view (grass pixels,
# is_grass, are a tenth of truth A and of DEFAULT's frame or more: the part covers about 0.4 of
# the view, its sparse blades over soil read as grass in part of it), and from 100 m DEFAULT
# draws no blades and some image-tier instances. An unknown camera is refused with the names of
# kScenes' cameras.
#   cmake -DMEASURE=<grass-measure> -DOUT=<dir> -P bench_cameras.cmake
file(REMOVE_RECURSE "${OUT}")
execute_process(
  COMMAND ${MEASURE} bench --scene hills --camera topdown --preset default --backend gl --size 96x54
          --frames 1 --out ${OUT} --references ${OUT}/references
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "bench --camera topdown: exit ${rc}\n${out}${err}")
endif()
file(READ "${OUT}/bench.csv" csv)
string(REGEX MATCHALL "\nhills,topdown,gl,default,[^\n]+" rows "${csv}")
list(LENGTH rows n)
if(NOT n EQUAL 1)
  message(FATAL_ERROR "${n} hills topdown rows in bench.csv, expected 1:\n${csv}")
endif()
string(REPLACE "," ";" cells "${rows}")
# geometry_instances, image_instances (columns 21 and 23, 0-based 20 and 22); grass_share and
# truth_grass_share (the last two).
list(GET cells 20 geometry)
list(GET cells 22 image)
list(GET cells -2 share)
list(GET cells -1 truth_share)
if(NOT geometry EQUAL 0 OR image LESS 1)
  message(SEND_ERROR "from 100 m up DEFAULT drew ${geometry} geometry and ${image} image instances, "
                     "expected none and some:\n${rows}")
endif()
# The shares of the view (if() compares numbers as doubles).
set(min_share 0.1)
foreach(name share truth_share)
  if(${name} LESS min_share)
    message(SEND_ERROR "${name} ${${name}}: the grass fills less than ${min_share} of the top-down view:\n${rows}")
  endif()
endforeach()

execute_process(COMMAND ${MEASURE} bench --camera nosuch RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 0 OR NOT "${out}${err}" MATCHES
                  "unknown camera \"nosuch\" \\(high, player, ant, grazing, third, elevated, strategy, topdown, flight\\)")
  message(SEND_ERROR "an unknown camera was not refused with the cameras' names: exit ${rc}\n${out}${err}")
endif()
