# cmake -DPREFIX=... -DSOURCE=... -DOUTPUT=... -DCXX=... -P pkg_config.cmake
# Consumer test: compiles SOURCE with `pkg-config --cflags --libs boxcyl-exact` from the installed
# PREFIX (and -std=c++20, which boxcyl.pc cannot impose), then runs it.
find_program(PKG_CONFIG pkg-config REQUIRED)
set(ENV{PKG_CONFIG_PATH} ${PREFIX}/share/pkgconfig)
execute_process(COMMAND ${PKG_CONFIG} --cflags --libs boxcyl-exact
                OUTPUT_VARIABLE flags OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pkg-config boxcyl-exact failed (${rc})")
endif()
if(NOT flags MATCHES "-I${PREFIX}/share/pkgconfig/\\.\\./\\.\\./include" OR NOT flags MATCHES "-lgmpxx")
  message(FATAL_ERROR "unexpected flags: ${flags}")
endif()
message(STATUS "pkg-config --cflags --libs boxcyl-exact: ${flags}")
separate_arguments(flags UNIX_COMMAND "${flags}")
execute_process(COMMAND ${CXX} -std=c++20 ${SOURCE} -o ${OUTPUT} ${flags} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "compiling ${SOURCE} with those flags failed (${rc})")
endif()
execute_process(COMMAND ${OUTPUT} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${OUTPUT} failed (${rc})")
endif()
