# Run by `cmake --install` (integration/python/CMakeLists.txt sets GRASS_PY_*): copies the
# grass package into <prefix>/lib/python3.X/site-packages (or dist-packages), writes
# grass/_config.py with the library's path relative to the package, and a dist-info so that
# pip and importlib.metadata know the package and its version.
set(prefix "${CMAKE_INSTALL_PREFIX}")
file(GLOB sites LIST_DIRECTORIES true RELATIVE "$ENV{DESTDIR}${prefix}"
     "$ENV{DESTDIR}${prefix}/lib/python3*/site-packages" "$ENV{DESTDIR}${prefix}/lib/python3*/dist-packages")
set(site "")
foreach(candidate IN LISTS sites)
  if(candidate MATCHES "^lib/python${GRASS_PY_PYTHON_VERSION}/")
    set(site "${candidate}")
  endif()
endforeach()
if(NOT site AND sites)
  list(GET sites 0 site)
endif()
if(NOT site)
  if(NOT GRASS_PY_PYTHON_VERSION)
    message(STATUS "grass: no lib/python3*/site-packages under ${prefix} and no Python found at configure time: "
                   "the Python package is not installed (integration/python works from PYTHONPATH)")
    return()
  endif()
  set(site "lib/python${GRASS_PY_PYTHON_VERSION}/site-packages")
endif()
set(package "${prefix}/${site}/grass")
file(GLOB modules "${GRASS_PY_SOURCE}/grass/*.py")
file(INSTALL ${modules} DESTINATION "${package}")

file(RELATIVE_PATH library "${package}" "${prefix}/${GRASS_PY_LIBRARY}")
set(config "${GRASS_PY_STAGE}/_config.py")
file(WRITE "${config}" "\"\"\"Written by cmake --install: the installed libgrass, relative to this package.\"\"\"
import os

LIBRARY = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), \"${library}\"))
")
file(INSTALL "${config}" DESTINATION "${package}")

set(info_name "grass-${GRASS_PY_VERSION}.dist-info")
set(info "${GRASS_PY_STAGE}/${info_name}")
file(REMOVE_RECURSE "${info}")
file(WRITE "${info}/METADATA" "Metadata-Version: 2.1\nName: grass\nVersion: ${GRASS_PY_VERSION}\n"
     "Summary: Python binding (ctypes) of the grass real-time grass renderer's C API\n")
file(WRITE "${info}/INSTALLER" "cmake\n")
set(record "")
file(GLOB installed RELATIVE "$ENV{DESTDIR}${prefix}/${site}" "$ENV{DESTDIR}${package}/*.py")
foreach(entry IN LISTS installed ITEMS ${info_name}/METADATA ${info_name}/INSTALLER ${info_name}/RECORD)
  string(APPEND record "${entry},,\n")
endforeach()
file(WRITE "${info}/RECORD" "${record}")
file(GLOB stale LIST_DIRECTORIES true "$ENV{DESTDIR}${prefix}/${site}/grass-*.dist-info")
if(stale)
  file(REMOVE_RECURSE ${stale})  # an earlier version's
endif()
file(INSTALL "${info}" DESTINATION "${prefix}/${site}")
