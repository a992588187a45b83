# The samples' and tools' command lines (ctest sample_cli): every tool and subcommand answers
# --help with its usage and exit 0, and refuses an unknown option and a bad --backend value
# with exit 2 and an error that names the option and the value. Nothing is rendered.
#   cmake -DRENDER=<grass-render> -DMEASURE=<grass-measure> [-DVIEWER=<grass-viewer>] -P cli_test.cmake
set(failures 0)

function(expect name expected_rc regex)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(text "${out}${err}")
  if(NOT rc STREQUAL "${expected_rc}")
    message(SEND_ERROR "${name}: exit ${rc}, expected ${expected_rc}\n${text}")
  elseif(NOT text MATCHES "${regex}")
    message(SEND_ERROR "${name}: the output does not match \"${regex}\":\n${text}")
  else()
    message(STATUS "${name}: ok")
  endif()
endfunction()

expect("grass-measure --help" 0 "Usage: grass-measure.*bench.*tier-cost.*popping.*dynamics" ${MEASURE} --help)
expect("grass-measure without a subcommand" 2 "subcommand is required" ${MEASURE})
expect("grass-measure with an unknown subcommand" 2 "not expected: frobnicate" ${MEASURE} frobnicate)

# tier-cost --single draws the plain table's single-cell rows only: not with --maps or --features.
expect("tier-cost --single --maps" 2 "--(single excludes --maps|maps excludes --single)" ${MEASURE} tier-cost --single --maps)
expect("tier-cost --features --single" 2 "--(single excludes --features|features excludes --single)" ${MEASURE} tier-cost
       --features --single)

# tier-cost --patch-of takes a scene file's patch: a missing file and a bad patch are refused
# by name (the latter before a host starts).
expect("tier-cost --patch-of nosuch.json" 2 "--patch-of: File does not exist: nosuch.json" ${MEASURE} tier-cost
       --patch-of nosuch.json)
file(WRITE "${CMAKE_CURRENT_BINARY_DIR}/cli-bad-patch.json" "{\"patch\": {\"blade_count\": -3}}")
expect("tier-cost --patch-of with a bad patch" 1 "--patch-of: .*cli-bad-patch.json: \"patch.blade_count\" is -3, out of range"
       ${MEASURE} tier-cost --patch-of "${CMAKE_CURRENT_BINARY_DIR}/cli-bad-patch.json")

# grass-render --lod-origin takes a point, as --camera does.
expect("grass-render --lod-origin 1,2" 2 "--lod-origin: \"1,2\" is not X,Y,Z" ${RENDER} --lod-origin 1,2)

set(tools "grass-render" "bench" "tier-cost" "popping" "dynamics")
if(VIEWER)
  list(APPEND tools "grass-viewer")
  # The viewer refuses what it cannot do before it opens a window (no display needed).
  expect("grass-viewer --quality best" 2 "--quality: .*best" ${VIEWER} --quality best)
  expect("grass-viewer --screenshot without --frames" 1 "--screenshot needs --frames N" ${VIEWER} --screenshot x.png)
  expect("grass-viewer --scene nosuch.json" 1 "cannot open nosuch.json" ${VIEWER} --scene nosuch.json)
endif()
foreach(tool IN LISTS tools)
  if(tool STREQUAL "grass-render")
    set(command ${RENDER})
    set(usage "Usage: grass-render")
  elseif(tool STREQUAL "grass-viewer")
    set(command ${VIEWER})
    set(usage "Usage: grass-viewer")
  else()
    set(command ${MEASURE} ${tool})
    set(usage "Usage: grass-measure ${tool}")
  endif()
  expect("${tool} --help" 0 "${usage}.*--backend" ${command} --help)
  expect("${tool} --no-such-option" 2 "--no-such-option" ${command} --no-such-option)
  expect("${tool} --backend dx" 2 "--backend: \"dx\" is not a backend" ${command} --backend dx)
  expect("${tool} --backend without a value" 2 "--backend" ${command} --backend)
  expect("${tool} --size 10" 2 "--size: \"10\" is not WxH" ${command} --size 10)
endforeach()

# grass-render's responsive-grass options: bad values are refused by name before anything renders.
expect("grass-render --frames 0" 2 "--frames: Value 0 not in range" ${RENDER} --frames 0)
expect("grass-render --fps 0" 2 "--fps: \"0\" is not between 0 and 10000" ${RENDER} --fps 0)
expect("grass-render --wind 1,0" 2 "--wind: \"1,0\" is not DX,DZ,SPEED\\[,GUST\\]" ${RENDER} --wind 1,0)
expect("grass-render --wind 0,0,3" 2 "--wind: \"0,0,3\": the direction DX,DZ is zero" ${RENDER} --wind 0,0,3)
expect("grass-render --blade-culling orientation,bogus" 2 "--blade-culling: bogus not in \\{orientation,frustum,distance-index,distance-threshold\\}" ${RENDER} --blade-culling orientation,bogus)
# The host's boxes, trees and cascaded shadows (docs/integration.md): bad lists refused by name.
expect("grass-render --host-shadows 10,5" 2 "--host-shadows: '10,5': split distances must be > 0 and ascending" ${RENDER}
       --host-shadows 10,5)
expect("grass-render --host-shadows of 5" 2 "--host-shadows: '1,2,3,4,5' has 5 numbers; expected 1 to 4" ${RENDER}
       --host-shadows 1,2,3,4,5)
expect("grass-render --box 1,2,3" 2 "--box: '1,2,3' has 3 numbers; expected 6" ${RENDER} --box 1,2,3)
expect("grass-render --box 1,x,3,4,5,6" 2 "--box: '1,x,3,4,5,6' is not a list of numbers \\('x'\\)" ${RENDER}
       --box 1,x,3,4,5,6)
expect("grass-render --tree 1,2,0,3" 2 "--tree: '1,2,0,3': the trunk and crown must be taller than 0" ${RENDER}
       --tree 1,2,0,3)
expect("popping --blade-culling bogus" 2 "--blade-culling: bogus not in" ${MEASURE} popping --blade-culling bogus)
expect("grass-render --collider cube:0,0,0,1" 2 "--collider: \"cube:0,0,0,1\" is not sphere:X,Y,Z,R"
       ${RENDER} --collider cube:0,0,0,1)
expect("grass-render --collider sphere:0,0,0" 2 "--collider: \"sphere:0,0,0\" is not sphere" ${RENDER} --collider
       sphere:0,0,0)

# glTF scenes: a bad file is refused before any rendering, with exit 2 and an error that
# names the file and what is wrong with it (tests/gltf holds the full list of hostile files).
set(scratch "${CMAKE_CURRENT_BINARY_DIR}/cli-test-gltf")
file(MAKE_DIRECTORY "${scratch}")
file(WRITE "${scratch}/short.glb" "glTF")
expect("grass-render --scene short.glb" 2 "short.glb: is 4 bytes: too short for a GLB header"
       ${RENDER} --scene "${scratch}/short.glb")
file(WRITE "${scratch}/bad-mesh.gltf"
     "{\"asset\": {\"version\": \"2.0\"}, \"scenes\": [{\"nodes\": [0]}], \"nodes\": [{\"name\": \"terrain\", \"mesh\": 3}]}")
expect("grass-render --scene bad-mesh.gltf" 2 "bad-mesh.gltf: .*node 0 \"terrain\" names mesh 3; the file has 0"
       ${RENDER} --scene "${scratch}/bad-mesh.gltf")
if(VIEWER)
  # The viewer refuses them the same way, before it opens a window.
  expect("grass-viewer --scene short.glb" 2 "grass-viewer: .*short.glb: is 4 bytes: too short for a GLB header"
         ${VIEWER} --scene "${scratch}/short.glb")
  expect("grass-viewer --scene bad-mesh.gltf" 2 "bad-mesh.gltf: .*node 0 \"terrain\" names mesh 3; the file has 0"
         ${VIEWER} --scene "${scratch}/bad-mesh.gltf")
endif()

# Values grass-render cannot honour are refused before anything renders (issue 37): NaN in
# any number (CLI::Range let it through: --density nan was ignored), a field of view outside
# (0, 180), frames whose times leave grass_view_desc.time's range (--time 1e9 --frames 3 failed
# only after the first frame), and in a scene file the same, named by the key.
expect("grass-render --density nan" 2 "--density: \"nan\" is not between 0 and 1" ${RENDER} --density nan)
expect("grass-render --time nan" 2 "--time: \"nan\" is not between" ${RENDER} --time nan)
expect("grass-render --camera nan,0,0" 2 "--camera: \"nan,0,0\" is not X,Y,Z \\(three finite numbers\\)" ${RENDER}
       --camera nan,0,0)
expect("grass-render --target 0,inf,0" 2 "--target: \"0,inf,0\" is not X,Y,Z" ${RENDER} --target 0,inf,0)
expect("grass-render --fov 180" 2 "--fov: \"180\" is not between 0 and 180 \\(exclusive\\)" ${RENDER} --fov 180)
expect("grass-render --fov -55" 2 "--fov: \"-55\" is not between 0 and 180" ${RENDER} --fov -55)
expect("grass-render --time 1e9 --frames 3" 2
       "--time 1000000000 with --frames 3 at --fps 24 puts the last frame at 1000000000.08[0-9]* s; a frame's time lies in \\[-1e9, 1e9\\]"
       ${RENDER} --time 1e9 --frames 3)
expect("popping --wind nan" 2 "--wind: \"nan\" is not between 0 and 1000" ${MEASURE} popping --wind nan)
set(scenes "${CMAKE_CURRENT_BINARY_DIR}/cli-test-scenes")
file(MAKE_DIRECTORY "${scenes}")
file(WRITE "${scenes}/fov.json" "{\"camera\": {\"fov\": -55}}")
expect("grass-render --scene fov.json" 1 "fov.json: \"camera.fov\" is -55; it must lie between 0 and 180" ${RENDER}
       --scene "${scenes}/fov.json")
file(WRITE "${scenes}/null.json" "null")
expect("grass-render --scene null.json" 1 "null.json: the scene must be an object, not null" ${RENDER}
       --scene "${scenes}/null.json")
file(WRITE "${scenes}/map-zero.json" "{\"field\": {\"density_map\": \"/dev/zero\"}}")
expect("grass-render --scene map-zero.json" 1 "map-zero.json: /dev/zero is a character device, not a regular file"
       ${RENDER} --scene "${scenes}/map-zero.json")
# Counts are refused before the work they imply: colliders past GRASS_MAX_COLLIDERS with
# --collider's, and capsules whose beads grass-render would have to build as meshes.
string(REPEAT "{\"centre\": [0, 0, 0]}," 65535 many)
file(WRITE "${scenes}/colliders.json" "{\"colliders\": [${many} {\"centre\": [0, 0, 0]}]}")
expect("grass-render 65536 colliders and --collider" 1 "the scene and --collider give 65537 colliders; grass takes at most 65536"
       ${RENDER} --scene "${scenes}/colliders.json" --collider sphere:0,0,0,1)
string(REPEAT "{\"shape\": \"capsule\", \"radius\": 0.01, \"centre\": [0, 0, 0], \"end\": [0, 10, 0]}," 99 legs)
file(WRITE "${scenes}/legs.json" "{\"colliders\": [${legs} {\"centre\": [0, 0, 0]}]}")
expect("grass-render 99 long capsules" 1 "the colliders and wind sources need 6337 meshes to draw; grass-render draws at most 4096"
       ${RENDER} --scene "${scenes}/legs.json")
