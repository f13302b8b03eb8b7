# Compiles the browser pages' static files (docs/viewer/) into the report library,
# so that a lesson can copy them next to its data wherever it runs (a student kit, a
# moved build) without looking for the source tree. Run as a script:
#   cmake -DOUTPUT=page_assets_data.cpp -DFILES="a.css|b.js" -P EmbedFiles.cmake
# Each file becomes an array of bytes (a string literal would pass -Wpedantic's
# limit of 4095 characters). The same script compiles in the openings of the lesson
# docs (docs/NN_topic.md, what each lesson page quotes): -DFUNCTION=doc_openings
# -DINCLUDE=gi/report/lesson_guide.hpp -DLIMIT=8192 keeps each file's first bytes.
if(NOT FUNCTION)
  set(FUNCTION page_assets)
  set(INCLUDE gi/report/page_assets.hpp)
endif()
string(REPLACE "|" ";" FILES "${FILES}")
set(body "")
set(table "")
set(index 0)
foreach(file ${FILES})
  get_filename_component(name ${file} NAME)
  if(LIMIT)
    file(READ ${file} hex LIMIT ${LIMIT} HEX)
  else()
    file(READ ${file} hex HEX)
  endif()
  string(LENGTH "${hex}" digits)
  math(EXPR size "${digits} / 2")
  string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," bytes "${hex}")
  string(REGEX REPLACE "(0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,)" "\\1\n" bytes "${bytes}")
  string(APPEND body "const unsigned char file_${index}[] = {\n${bytes}0};\n")
  string(APPEND table "      {\"${name}\", std::string_view(reinterpret_cast<const char*>(file_${index}), ${size})},\n")
  math(EXPR index "${index} + 1")
endforeach()
file(WRITE ${OUTPUT}.new "// Made by cmake/EmbedFiles.cmake from files of docs/ at build time: edit those files, not this one.
#include \"${INCLUDE}\"

namespace gi {

namespace {
${body}}  // namespace

const std::vector<PageAsset>& ${FUNCTION}() {
  static const std::vector<PageAsset> assets = {
${table}  };
  return assets;
}

}  // namespace gi
")
# Rewritten only when it changed, so that an unchanged page does not rebuild the library.
file(COPY_FILE ${OUTPUT}.new ${OUTPUT} ONLY_IF_DIFFERENT)
file(REMOVE ${OUTPUT}.new)
