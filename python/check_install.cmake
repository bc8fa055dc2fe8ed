# Installs the build into WORK_DIR/prefix and imports unfurl from there
# with PYTHON (the package, not the build tree's copy); and checks that the
# default prefix's directory is one the interpreter searches, so a plain
# `cmake --install` puts the package where `import unfurl` finds it.
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix
                RESULT_VARIABLE status OUTPUT_QUIET)
if(status)
  message(FATAL_ERROR "cmake --install failed (${status})")
endif()
set(site ${WORK_DIR}/prefix/${INSTALL_DIR})
execute_process(
  COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${site} ${PYTHON} -c
          "import unfurl, sys; assert unfurl.__file__.startswith(sys.argv[1]), unfurl.__file__; r = unfurl.simulate('pantograph', t_end=8, rtol=1e-8); print('imported from the prefix:', len(r.events), 'latches')"
          ${site}
  WORKING_DIRECTORY ${WORK_DIR}  # not the build tree, whose unfurl/ would be imported first
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(status)
  message(FATAL_ERROR "importing the installed package failed (${status})")
endif()
execute_process(COMMAND ${PYTHON} -c "import sys; print('\\n'.join(sys.path))" OUTPUT_VARIABLE paths)
if(NOT paths MATCHES "${DEFAULT_PREFIX}/${INSTALL_DIR}")
  message(FATAL_ERROR "${PYTHON} does not search ${DEFAULT_PREFIX}/${INSTALL_DIR}, where cmake --install puts unfurl")
endif()
