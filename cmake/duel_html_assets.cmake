# duel_html_assets.cmake - the web pages' viewer (tools/render/html/viewer.js and viewer.css) as C arrays with their
# Content-Security-Policy hashes (base64 of SHA-256), generated at build time into duel_html_assets.c.
#
# As a module: duel_html_assets(OUT_VAR) adds the custom command and sets OUT_VAR to the generated file.
# As a script (cmake -DJS=... -DCSS=... -DOUT=... -P duel_html_assets.cmake): writes OUT.

# hex digits -> base64, 3 bytes at a time
function(_duel_hex_to_b64 hex out)
  set(alphabet "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/")
  string(LENGTH "${hex}" n)
  set(res "")
  set(i 0)
  while(i LESS n)
    math(EXPR left "${n} - ${i}")
    if(left GREATER_EQUAL 6)
      string(SUBSTRING "${hex}" ${i} 6 chunk)
      set(pad 0)
    elseif(left EQUAL 4)
      string(SUBSTRING "${hex}" ${i} 4 chunk)
      set(chunk "${chunk}00")
      set(pad 1)
    else()
      string(SUBSTRING "${hex}" ${i} 2 chunk)
      set(chunk "${chunk}0000")
      set(pad 2)
    endif()
    math(EXPR v "0x${chunk}")
    math(EXPR c0 "(${v} >> 18) & 63")
    math(EXPR c1 "(${v} >> 12) & 63")
    math(EXPR c2 "(${v} >> 6) & 63")
    math(EXPR c3 "${v} & 63")
    string(SUBSTRING "${alphabet}" ${c0} 1 a0)
    string(SUBSTRING "${alphabet}" ${c1} 1 a1)
    string(SUBSTRING "${alphabet}" ${c2} 1 a2)
    string(SUBSTRING "${alphabet}" ${c3} 1 a3)
    if(pad EQUAL 0)
      string(APPEND res "${a0}${a1}${a2}${a3}")
    elseif(pad EQUAL 1)
      string(APPEND res "${a0}${a1}${a2}=")
    else()
      string(APPEND res "${a0}${a1}==")
    endif()
    math(EXPR i "${i} + 6")
  endwhile()
  set(${out} "${res}" PARENT_SCOPE)
endfunction()

# one asset: its bytes as a C array, its length and its hash
function(_duel_asset path name out)
  file(READ "${path}" text)
  # the page puts the file inside <script> or <style>: a closing tag or a comment opener in it would end that early
  string(TOLOWER "${text}" lower)
  foreach(bad "</script" "</style" "<!--")
    string(FIND "${lower}" "${bad}" at)
    if(NOT at EQUAL -1)
      message(FATAL_ERROR "${path}: holds '${bad}', which would end its element in the page")
    endif()
  endforeach()
  file(READ "${path}" hex HEX)
  file(SHA256 "${path}" sha)
  _duel_hex_to_b64("${sha}" b64)
  string(LENGTH "${hex}" hexlen)
  math(EXPR len "${hexlen} / 2")
  string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," body "${hex}")
  string(REGEX REPLACE "((0x[0-9a-f][0-9a-f],){24})" "\\1\n" body "${body}")
  set(${out} "const unsigned char ${name}[] = {\n${body}0x00};\nconst size_t ${name}_len = ${len};\nconst char ${name}_sha256[] = \"${b64}\";\n" PARENT_SCOPE)
endfunction()

if(CMAKE_SCRIPT_MODE_FILE AND DEFINED OUT)
  _duel_asset("${JS}" duel_html_js js_c)
  _duel_asset("${CSS}" duel_html_css css_c)
  file(WRITE "${OUT}.tmp" "/* generated from tools/render/html/ by cmake/duel_html_assets.cmake: do not edit */\n"
       "#include \"duel_html_assets.h\"\n\n${js_c}\n${css_c}")
  file(RENAME "${OUT}.tmp" "${OUT}")
  return()
endif()

set(_DUEL_HTML_ASSETS_SCRIPT "${CMAKE_CURRENT_LIST_FILE}")
function(duel_html_assets out_var)
  set(dir "${PROJECT_SOURCE_DIR}/tools/render/html")
  set(out "${CMAKE_CURRENT_BINARY_DIR}/duel_html_assets.c")
  add_custom_command(OUTPUT "${out}"
                     COMMAND ${CMAKE_COMMAND} -DJS=${dir}/viewer.js -DCSS=${dir}/viewer.css -DOUT=${out}
                             -P "${_DUEL_HTML_ASSETS_SCRIPT}"
                     DEPENDS "${dir}/viewer.js" "${dir}/viewer.css" "${_DUEL_HTML_ASSETS_SCRIPT}"
                     COMMENT "Embedding the web pages' viewer" VERBATIM)
  set(${out_var} "${out}" PARENT_SCOPE)
endfunction()
