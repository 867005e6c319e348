// boxcyl: command-line front end; everything happens in app.cpp and jsonl_query.cpp.
#include "app.hpp"

int main(int argc, char** argv) { return boxcyl::cli::run_app(argc, argv); }
