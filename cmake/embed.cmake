# Turns a data file into a C++ source defining `std::string_view NAME()`, so the
# binary carries data/ (error texts, machine profiles) without an install step.
# Usage: cmake -DIN=file -DOUT=file.cpp -DNAME=symbol -P embed.cmake
file(READ "${IN}" content HEX)
string(LENGTH "${content}" n)
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "'\\\\x\\1'," bytes "${content}")
file(WRITE "${OUT}" "// generated from ${IN} by cmake/embed.cmake; do not edit\n#include <string_view>\nnamespace pupitre::data {\nstatic const char bytes_[] = {${bytes} 0};\nstd::string_view ${NAME}() { return {bytes_, sizeof bytes_ - 1}; }\n}\n")
