# cmake -DINPUT=page.html -DOUTPUT=studio_page.cpp -P embed.cmake: the page as the bytes of a C++
# array, returned by tactus::cli::studio_page() (page.hpp).
file(READ ${INPUT} hex HEX)
string(LENGTH "${hex}" length)
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," bytes "${hex}")
math(EXPR size "${length} / 2")
file(WRITE ${OUTPUT}
  "// Generated from page.html by embed.cmake.\n#include \"page.hpp\"\n"
  "namespace tactus::cli {\nnamespace {\nconstexpr char kPage[] = {${bytes}0};\n}\n"
  "std::string_view studio_page() { return {kPage, ${size}}; }\n}  // namespace tactus::cli\n")
