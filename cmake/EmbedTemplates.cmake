# Script mode: embed the text of template files into a C++ source, so the rbdgen executable carries
# its templates (an installed rbdgen needs no data files).
#   cmake -DOUTPUT=embedded.cpp -DINPUTS="a.in;b.in" -P EmbedTemplates.cmake
# Each file becomes an entry {"<file name>", R"...(<text>)..."} of rbdgen::embeddedTemplates().
set(body "")
foreach(input IN LISTS INPUTS)
  file(READ ${input} text)
  get_filename_component(name ${input} NAME)
  string(FIND "${text}" ")rbdgen_tpl\"" clash)
  if(NOT clash EQUAL -1)
    message(FATAL_ERROR "${input}: contains the raw-string delimiter )rbdgen_tpl\"")
  endif()
  string(APPEND body "    {\"${name}\", R\"rbdgen_tpl(${text})rbdgen_tpl\"},\n")
endforeach()
file(WRITE ${OUTPUT}.tmp "// Generated from templates/ by cmake/EmbedTemplates.cmake. Do not edit.
#include <map>
#include <string>

namespace rbdgen
{

const std::map<std::string, std::string> & embeddedTemplates()
{
  static const std::map<std::string, std::string> templates{
${body}  };
  return templates;
}

} // namespace rbdgen
")
file(COPY_FILE ${OUTPUT}.tmp ${OUTPUT} ONLY_IF_DIFFERENT)
file(REMOVE ${OUTPUT}.tmp)
