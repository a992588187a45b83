# The window test (ctest viewer_window_<backend>_<variant>, label window): under xvfb-run,
# grass-viewer renders a few frames of a scripted camera in its window and writes the
# presented image; grass-render renders the same camera headless; grass_viewer_compare checks
# they match within the stated tolerance and that both show grass. A second headless image
# from a camera 0.5 m to the side must NOT match (the test catches a wrong camera; with
# WRONG_CAMERA=ON, one variant per backend: each grass-render run costs seconds).
#   cmake -DVIEWER= -DRENDER= -DCOMPARE= -DXVFB_RUN= -DBACKEND=gl|vk -DSAMPLES=1|4 -DGROUND=ON|OFF [-DWRONG_CAMERA=ON]
#         [-DSCRIPT=<grass-viewer --script> -DFINAL_SIZE=WxH -DFINAL_SAMPLES=1|4] [-DSCENE=<scene file>]
#         -DOUT=<dir> -P viewer_window_test.cmake
# With SCRIPT the viewer also goes through scripted keys and window sizes first (MSAA, presets,
# a resize); the headless image is then made at the window's final size and sample count.
# With SCENE (e.g. a glTF file) both tools load that file and use its camera.
set(size 160x90)
set(camera 0.4,1.2,-5.5)
set(target 0,0.1,1)
set(other_camera 0.9,1.2,-5.5)
set(frames 3)
set(viewer_args --backend ${BACKEND} --size ${size} --samples ${SAMPLES})
if(NOT FINAL_SIZE)
  set(FINAL_SIZE ${size})
endif()
if(NOT FINAL_SAMPLES)
  set(FINAL_SAMPLES ${SAMPLES})
endif()
set(render_args --backend ${BACKEND} --size ${FINAL_SIZE} --samples ${FINAL_SAMPLES})
if(SCRIPT)
  set(frames 6)
  list(APPEND viewer_args --script ${SCRIPT})
endif()
set(view_args --camera ${camera} --target ${target})
if(SCENE)
  list(APPEND viewer_args --scene ${SCENE})
  list(APPEND render_args --scene ${SCENE})
  set(view_args) # the file's camera
endif()
if(NOT GROUND)
  list(APPEND viewer_args --no-ground)
  list(APPEND render_args --no-ground)
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
run("grass-viewer" ${XVFB_RUN} -a -s "-screen 0 640x480x24" ${VIEWER} ${viewer_args} ${view_args}
    --frames ${frames} --screenshot ${OUT}/window.png --exit --no-overlay --no-vsync)
run("grass-render" ${RENDER} ${render_args} ${view_args} --output ${OUT}/headless.png)
run("window vs headless" ${COMPARE} ${OUT}/window.png ${OUT}/headless.png same)
if(WRONG_CAMERA)
  run("grass-render, another camera" ${RENDER} ${render_args} --camera ${other_camera} --target ${target}
      --output ${OUT}/other.png)
  run("window vs another camera" ${COMPARE} ${OUT}/window.png ${OUT}/other.png different)
endif()
