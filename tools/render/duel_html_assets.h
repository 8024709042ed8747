/* duel_html_assets.h - the viewer's script and style sheet (tools/render/html/), embedded at build time with their CSP hashes (cmake/duel_html_assets.cmake). */
#ifndef DUEL_HTML_ASSETS_H
#define DUEL_HTML_ASSETS_H

#include <stddef.h>

extern const unsigned char duel_html_js[];
extern const size_t duel_html_js_len;
extern const char duel_html_js_sha256[];  /* base64 of the script's SHA-256, for script-src */
extern const unsigned char duel_html_css[];
extern const size_t duel_html_css_len;
extern const char duel_html_css_sha256[]; /* the style sheet's, for style-src */

#endif /* DUEL_HTML_ASSETS_H */
