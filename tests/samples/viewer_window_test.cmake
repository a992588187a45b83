# The viewer window test (ctest viewer_window_<backend>_<variant>, label window): under
# xvfb-run, grass-viewer renders FRAMES frames of a scripted camera in its window and writes
# the presented image; grass-render renders the same camera headless; grass_viewer_compare
# checks they match within the stated tolerance and that both show grass. A second headless
# image from a camera 0.5 m to the side must NOT match (the test catches a wrong camera).
#   cmake -DVIEWER= -DRENDER= -DCOMPARE= -DXVFB_RUN= -DBACKEND=gl|vk -DSAMPLES=1|4 -DGROUND=ON|OFF
#         -DOUT=<dir> -P viewer_window_test.cmake
set(size 160x90)
set(camera 0.4,1.2,-5.5)
set(target 0,0.1,1)
set(other_camera 0.9,1.2,-5.5)
set(common --backend ${BACKEND} --size ${size} --samples ${SAMPLES})
if(NOT GROUND)
  list(APPEND common --no-ground)
endif()
file(MAKE_DIRECTORY ${OUT})

function(run name)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "${name}: ${out}${err}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${name} failed with exit ${rc}")
  endif()
endfunction()

# A 24-bit screen (xvfb-run's default is 8-bit, which has no GL or Vulkan visual).
run("grass-viewer" ${XVFB_RUN} -a -s "-screen 0 640x480x24" ${VIEWER} ${common} --camera ${camera}
    --target ${target} --frames 3 --screenshot ${OUT}/window.png --exit --no-overlay --no-vsync)
run("grass-render" ${RENDER} ${common} --camera ${camera} --target ${target} --output ${OUT}/headless.png)
run("grass-render, another camera" ${RENDER} ${common} --camera ${other_camera} --target ${target}
    --output ${OUT}/other.png)
run("window vs headless" ${COMPARE} ${OUT}/window.png ${OUT}/headless.png same)
run("window vs another camera" ${COMPARE} ${OUT}/window.png ${OUT}/other.png different)
