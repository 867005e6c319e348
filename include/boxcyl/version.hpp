// boxcyl's version (kept in step with project(VERSION) in CMakeLists.txt; a test checks it).
#pragma once

#define BOXCYL_VERSION_MAJOR 0
#define BOXCYL_VERSION_MINOR 1
#define BOXCYL_VERSION_PATCH 0
#define BOXCYL_VERSION_STRING "0.1.0"
