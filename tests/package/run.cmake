# ctest package_install: cmake --install the build tree into WORK/prefix, configure and build
# tests/package against it as an outside project would, run the example and check its PLY.
# Arguments: -DBUILD_DIR=<shadowvol build tree> -DSOURCE_DIR=<shadowvol source> -DWORK=<scratch>,
# and with the Python module -DPYTHON=<its interpreter> -DPYTHON_DIR=<its install folder in the prefix>;
# in a sanitizer build -DSANITIZE_FLAGS=<the -fsanitize flags the outside project must build with>.
file(REMOVE_RECURSE ${WORK})
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
endfunction()
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK}/prefix)
set(sanitize)
if(SANITIZE_FLAGS)
  set(sanitize -DCMAKE_CXX_FLAGS=${SANITIZE_FLAGS} -DCMAKE_EXE_LINKER_FLAGS=${SANITIZE_FLAGS})
endif()
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/package -B ${WORK}/build -DCMAKE_BUILD_TYPE=Release
    -DCMAKE_PREFIX_PATH=${WORK}/prefix -DSHADOWVOL_EXAMPLE_SOURCE=${SOURCE_DIR}/apps/minimal_volume.cpp ${sanitize})
run(${CMAKE_COMMAND} --build ${WORK}/build)
run(${WORK}/build/minimal_volume ${WORK}/volume.ply)
run(${WORK}/build/link_all)
if(EXISTS ${WORK}/prefix/bin/shadowvol)  # the installed command runs (with shared libraries: finds them)
  run(${WORK}/prefix/bin/shadowvol -q build --resolution 32 --out ${WORK}/cli-volume.glb)
endif()
file(SIZE ${WORK}/volume.ply size)
if(size LESS 1000)
  message(FATAL_ERROR "minimal_volume wrote ${size} bytes")
endif()
# The installed Python module, when the build has one: import it from the prefix and build a volume.
if(PYTHON)
  file(GLOB module ${WORK}/prefix/${PYTHON_DIR}/shadowvol*.so)
  if(NOT module)
    message(FATAL_ERROR "the Python module is not installed in ${WORK}/prefix/${PYTHON_DIR}")
  endif()
  run(${CMAKE_COMMAND} -E env PYTHONPATH=${WORK}/prefix/${PYTHON_DIR} ${PYTHON} -c
      "import shadowvol as sv; V, F, s = sv.build_volume(sv.capture_depth(sv.default_scene(), 64, 64)); assert len(F) > 0")
endif()
message(STATUS "outside project built against ${WORK}/prefix; volume.ply ${size} bytes")
