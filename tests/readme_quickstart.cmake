# cmake -DREADME=<README.md> -DSOURCE=<examples/quickstart.cpp> -P readme_quickstart.cmake
# (CTest: readme.quickstart_matches). The README shows the quick-start program verbatim: the whole file,
# as one ```cpp block. consumer.quickstart builds and runs the file itself.
file(READ ${README} readme)
file(READ ${SOURCE} source)
string(FIND "${readme}" "```cpp\n${source}```\n" at)
if(at EQUAL -1)
  message(FATAL_ERROR "${README} does not show ${SOURCE} verbatim as a ```cpp block; copy the file into it")
endif()
message(STATUS "${README} shows ${SOURCE} verbatim")
