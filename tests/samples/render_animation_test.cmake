# grass-render --animation (ctest render_animation_<backend>): three tiny frames of the demo
# lawn with wind and a rolling ball, 0.25 s apart. The frames, the GIF and the MP4 exist and
# are not empty, the frames differ from one another (the grass moves), the last frame is the
# --output image, and a stale frame of an earlier run in the directory is gone.
#   cmake -DRENDER=<grass-render> -DBACKEND=gl|vk -DOUT=<dir> -P render_animation_test.cmake
file(REMOVE_RECURSE "${OUT}")
# A frame left by an earlier, longer run into the same directory: removed, not animated.
file(WRITE "${OUT}/animation/frame-0003.png" "a stale frame")
execute_process(
  COMMAND ${RENDER} --backend ${BACKEND} --size 96x54 --samples 1 --frames 3 --fps 4 --time 10
          --wind 1,0.3,6,0.8 --collider sphere:-1,0.3,0,0.35,3,0,0
          --camera 0,1.4,-3 --target 0,0,1 --animation "${OUT}/animation" --output "${OUT}/last.png"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "grass-render exited with ${rc}:\n${out}${err}")
endif()
message(STATUS "${out}")
foreach(name frame-0000.png frame-0001.png frame-0002.png animation.gif animation.mp4)
  set(path "${OUT}/animation/${name}")
  if(NOT EXISTS "${path}")
    message(FATAL_ERROR "${name} was not written:\n${out}${err}")
  endif()
  file(SIZE "${path}" size)
  if(size LESS 200)
    message(FATAL_ERROR "${name} has ${size} bytes: too small to hold an image")
  endif()
endforeach()
if(EXISTS "${OUT}/animation/frame-0003.png")
  message(FATAL_ERROR "a fourth frame (stale or written) is there after --frames 3")
endif()
# Each frame differs from the one before (the wind and the ball move), the last is --output.
foreach(pair "0000;0001" "0001;0002")
  list(GET pair 0 a)
  list(GET pair 1 b)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${OUT}/animation/frame-${a}.png"
                          "${OUT}/animation/frame-${b}.png" RESULT_VARIABLE same)
  if(same EQUAL 0)
    message(FATAL_ERROR "frame-${a}.png and frame-${b}.png are the same image: nothing moved")
  endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${OUT}/animation/frame-0002.png" "${OUT}/last.png"
                RESULT_VARIABLE differ)
if(NOT differ EQUAL 0)
  message(FATAL_ERROR "--output is not the last frame")
endif()
# The GIF holds the three frames (ffprobe counts them), the MP4 is H.264.
find_program(FFPROBE ffprobe)
function(expect_stream file expected)
  execute_process(COMMAND ${FFPROBE} -v error -count_frames -select_streams v:0 -show_entries
                          stream=codec_name,nb_read_frames -of csv=p=0 "${OUT}/animation/${file}"
                  OUTPUT_VARIABLE found OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT found STREQUAL expected)
    message(FATAL_ERROR "${file}: ffprobe says \"${found}\", expected ${expected}")
  endif()
endfunction()
if(FFPROBE)
  expect_stream(animation.gif "gif,3")
  expect_stream(animation.mp4 "h264,3")
endif()
