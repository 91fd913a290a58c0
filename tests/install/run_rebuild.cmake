# Script mode (Ninja): the rebuild behaviour of generate_robot_dynamics() in a downstream project.
# Install BUILD_DIR into PREFIX, copy the installed pendulum.urdf into WORK, build the consumer
# against that copy, then:
#   (a) a second build does no work;
#   (b) touching the URDF reruns rbdgen, whose unchanged header keeps its mtime, so the consumer
#       is not recompiled (Ninja restat), and the build after that does no work again;
#   (c) changing the URDF (the bob's mass) regenerates the header and recompiles the consumer,
#       whose closed-form check (m = 1 kg) must now fail: proof that the new header is in it.
function(run out_var)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "command failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  set(${out_var} "${out}\n${err}" PARENT_SCOPE)
endfunction()
function(expect text regex what)
  if(NOT text MATCHES "${regex}")
    message(FATAL_ERROR "${what}: expected /${regex}/ in the build output:\n${text}")
  endif()
endfunction()
function(expect_not text regex what)
  if(text MATCHES "${regex}")
    message(FATAL_ERROR "${what}: unexpected /${regex}/ in the build output:\n${text}")
  endif()
endfunction()
macro(pause) # mtimes must move even on a file system with 1 s resolution
  execute_process(COMMAND ${CMAKE_COMMAND} -E sleep 1.1)
endmacro()

set(build ${WORK}/consumer-build)
set(urdf ${WORK}/robot/pendulum.urdf)
file(REMOVE_RECURSE ${PREFIX} ${WORK})
run(out ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${PREFIX})
file(COPY ${PREFIX}/${DATADIR}/rbdgen/robots/pendulum.urdf DESTINATION ${WORK}/robot)
run(out ${CMAKE_COMMAND} -S ${CONSUMER_SRC} -B ${build} -G ${GENERATOR}
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${PREFIX} -DRBDGEN_PENDULUM_URDF=${urdf}
    -DCMAKE_CXX_COMPILER=${CONSUMER_CXX} "-DCMAKE_CXX_FLAGS=${CONSUMER_CXX_FLAGS}"
    "-DCMAKE_EXE_LINKER_FLAGS=${CONSUMER_LINKER_FLAGS}")
set(header ${build}/pendulum_dynamics/pendulum/dynamics.hpp)
# The consumer's compile line. (-d explain also lists main.cpp.o as "dirty" before the restat of
# the header prunes it: only the compile line proves it was compiled.)
set(object "Building CXX object [^\n]*main\\.cpp\\.o")
set(generate "rbdgen: .*pendulum/dynamics\\.hpp") # the custom command's COMMENT

run(out ${CMAKE_COMMAND} --build ${build} -- -d explain)
expect("${out}" "${generate}" "first build")
expect("${out}" "${object}" "first build")
run(out ${build}/consumer)
message(STATUS "first build: ok")

# (a) nothing changed: no work.
run(out ${CMAKE_COMMAND} --build ${build} -- -d explain)
expect("${out}" "ninja: no work to do" "(a) second build")
message(STATUS "(a) second build: no work to do")

# (b) touched, same content: rbdgen runs, the header is kept, the consumer is not recompiled.
file(READ ${header} header_before)
file(TIMESTAMP ${header} stamp_before "%s")
pause()
file(TOUCH ${urdf})
run(out ${CMAKE_COMMAND} --build ${build} -- -d explain)
expect("${out}" "${generate}" "(b) touched URDF")
expect_not("${out}" "${object}" "(b) touched URDF")
expect_not("${out}" "Building CXX|Linking CXX" "(b) touched URDF")
file(READ ${header} header_after)
file(TIMESTAMP ${header} stamp_after "%s")
if(NOT header_after STREQUAL header_before OR NOT stamp_after STREQUAL stamp_before)
  message(FATAL_ERROR "(b) the header was rewritten (mtime ${stamp_before} -> ${stamp_after})")
endif()
run(out ${CMAKE_COMMAND} --build ${build} -- -d explain)
expect("${out}" "ninja: no work to do" "(b) build after the touched one")
message(STATUS "(b) touched URDF: rbdgen ran, header kept, consumer not recompiled")

# (c) changed content: header regenerated, consumer recompiled (and now sees m = 2 kg).
pause()
file(READ ${urdf} text)
string(REPLACE "<mass value=\"1\"/>" "<mass value=\"2\"/>" changed "${text}")
if(changed STREQUAL text)
  message(FATAL_ERROR "(c) pendulum.urdf has no <mass value=\"1\"/> to change")
endif()
file(WRITE ${urdf} "${changed}")
run(out ${CMAKE_COMMAND} --build ${build} -- -d explain)
expect("${out}" "${generate}" "(c) changed URDF")
expect("${out}" "${object}" "(c) changed URDF")
file(READ ${header} header_changed)
if(header_changed STREQUAL header_before)
  message(FATAL_ERROR "(c) the header did not change")
endif()
execute_process(COMMAND ${build}/consumer RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 0 OR NOT out MATCHES "gravity_torques[^\n]*FAIL" OR NOT out MATCHES "runtime holding torque[^\n]*ok")
  message(FATAL_ERROR "(c) the rebuilt consumer should fail its m = 1 kg checks only (exit ${rc}):\n${out}\n${err}")
endif()
message(STATUS "(c) changed URDF: header regenerated, consumer recompiled (its m = 1 kg check now fails, as it must)")
