# cmake -DPYTHON=... -DSOURCE_DIR=<repo> -DWORK_DIR=... -P pip_install_test.cmake  (CTest: python.pip_install)
# Checks the documented install path: `pip install --no-build-isolation` of python/ with Debian's
# setuptools/pybind11/numpy, here into a --target directory (the README shows a venv), then runs the
# pytest suite against that install only. python/, include/ and src/ are copied first, because
# setuptools builds in the source directory and a test must not write into the checkout.
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR}/src)
file(COPY ${SOURCE_DIR}/include ${SOURCE_DIR}/python ${SOURCE_DIR}/src DESTINATION ${WORK_DIR}/src
     PATTERN build EXCLUDE PATTERN *.egg-info EXCLUDE PATTERN __pycache__ EXCLUDE)
execute_process(COMMAND ${PYTHON} -m pip install --quiet --no-build-isolation --no-deps --no-index
                        --target ${WORK_DIR}/site ${WORK_DIR}/src/python
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pip install failed (${rc})")
endif()
set(ENV{PYTHONPATH} ${WORK_DIR}/site)
set(ENV{PYTHONDONTWRITEBYTECODE} 1)
execute_process(COMMAND ${PYTHON} -c "import boxcyl, sys; assert boxcyl.__file__.startswith(sys.argv[1]), boxcyl.__file__"
                        ${WORK_DIR}/site
                WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the installed boxcyl is not the one imported")
endif()
execute_process(COMMAND ${PYTHON} -m pytest -q -p no:cacheprovider ${WORK_DIR}/src/python/tests
                WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pytest against the pip-installed package failed (${rc})")
endif()
