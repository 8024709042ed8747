/* duel_html.c - a self-contained web page: the skeleton with its inline viewer and CSP, JSON strings safe in a script element, and a duel's data (world, sides, networks, frames as base64). */
#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "duel_html.h"
#include "duel_html_assets.h"
#include "duel_netgraph.h"
#include "duel_trace.h"

static const char *duel_html_generator = "neat-duel";

void duel_html_set_generator(const char *name)
{
    duel_html_generator = name != NULL ? name : "neat-duel";
}

void duel_html_open(FILE *f)
{
    fputs("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n", f);
    /* nothing but the page's own script and style (by hash) runs or loads: a hostile string in the data
     * cannot become markup, and the page makes no request */
    fprintf(f,
            "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; script-src 'sha256-%s'; "
            "style-src 'sha256-%s'; img-src data:; base-uri 'none'; form-action 'none'\">\n",
            duel_html_js_sha256, duel_html_css_sha256);
    fputs("<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n", f);
    fputs("<meta name=\"generator\" content=\"", f);
    /* the generator is ours (a version string), but keep it attribute-safe anyway */
    {
        const char *s;
        for (s = duel_html_generator; *s; s++)
            if (*s != '"' && *s != '<' && *s != '>' && *s != '&' && (unsigned char)*s >= 0x20)
                fputc(*s, f);
    }
    fputs("\">\n<title>neat-duel</title>\n<style>", f);
    fwrite(duel_html_css, 1, duel_html_css_len, f);
    fputs("</style>\n</head>\n<body>\n<noscript>This page draws with JavaScript, which is off.</noscript>\n"
          "<div id=\"app\"></div>\n<script type=\"application/json\" id=\"duel-data\">",
          f);
}

void duel_html_close(FILE *f)
{
    fputs("</script>\n<script>", f);
    fwrite(duel_html_js, 1, duel_html_js_len, f);
    fputs("</script>\n</body>\n</html>\n", f);
}

/* The length of the UTF-8 sequence at s (1..4), or 0 when it is not one
 * (overlong forms, surrogates and code points above U+10FFFF included). */
static int duel_html_utf8(const unsigned char *s, uint32_t *cp)
{
    int n, i;
    uint32_t c = s[0];
    if (c < 0x80) {
        *cp = c;
        return 1;
    }
    if (c >= 0xc2 && c <= 0xdf)
        n = 2, c &= 0x1f;
    else if (c >= 0xe0 && c <= 0xef)
        n = 3, c &= 0x0f;
    else if (c >= 0xf0 && c <= 0xf4)
        n = 4, c &= 0x07;
    else
        return 0;
    for (i = 1; i < n; i++) {
        if ((s[i] & 0xc0) != 0x80)
            return 0;
        c = (c << 6) | (s[i] & 0x3f);
    }
    if ((n == 3 && (c < 0x800 || (c >= 0xd800 && c <= 0xdfff))) || (n == 4 && (c < 0x10000 || c > 0x10ffff)))
        return 0;
    *cp = c;
    return n;
}

void duel_html_str(FILE *f, const char *str)
{
    const unsigned char *s = (const unsigned char *)str;
    fputc('"', f);
    while (*s) {
        uint32_t cp;
        int n = duel_html_utf8(s, &cp);
        if (n == 0) {
            fputs("\\ufffd", f);
            s++;
            continue;
        }
        if (cp == '"' || cp == '\\')
            fprintf(f, "\\%c", (int)cp);
        else if (cp < 0x20 || cp == 0x7f || cp == '<' || cp == '>' || cp == '&' || cp == 0x2028 || cp == 0x2029)
            fprintf(f, "\\u%04x", (unsigned)cp);
        else
            fwrite(s, 1, (size_t)n, f);
        s += n;
    }
    fputc('"', f);
}

/* len bytes in base64, unquoted */
static void duel_html_b64_raw(FILE *f, const void *data, size_t len)
{
    static const char t[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    const uint8_t *p = (const uint8_t *)data;
    size_t i;
    for (i = 0; i + 3 <= len; i += 3) {
        uint32_t v = ((uint32_t)p[i] << 16) | ((uint32_t)p[i + 1] << 8) | p[i + 2];
        fputc(t[v >> 18], f);
        fputc(t[(v >> 12) & 63], f);
        fputc(t[(v >> 6) & 63], f);
        fputc(t[v & 63], f);
    }
    if (len - i == 1) {
        uint32_t v = (uint32_t)p[i] << 16;
        fputc(t[v >> 18], f);
        fputc(t[(v >> 12) & 63], f);
        fputs("==", f);
    } else if (len - i == 2) {
        uint32_t v = ((uint32_t)p[i] << 16) | ((uint32_t)p[i + 1] << 8);
        fputc(t[v >> 18], f);
        fputc(t[(v >> 12) & 63], f);
        fputc(t[(v >> 6) & 63], f);
        fputc('=', f);
    }
}

void duel_html_b64(FILE *f, const void *data, size_t len)
{
    fputc('"', f);
    duel_html_b64_raw(f, data, len);
    fputc('"', f);
}

void duel_html_data_uri(FILE *f, const char *mime, const void *data, size_t len)
{
    fprintf(f, "\"data:%s;base64,", mime);
    duel_html_b64_raw(f, data, len);
    fputc('"', f);
}

void duel_html_common(FILE *f, const char *kind, const char *title)
{
    fprintf(f, "\"format\":\"neat-duel-page\",\"version\":%d,\"kind\":", DUEL_HTML_VERSION);
    duel_html_str(f, kind);
    fputs(",\"generator\":", f);
    duel_html_str(f, duel_html_generator);
    fputs(",\"title\":", f);
    duel_html_str(f, title);
    fputc(',', f);
}

/* little-endian stores, whatever the host */
static void duel_html_le32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)v;
    p[1] = (uint8_t)(v >> 8);
    p[2] = (uint8_t)(v >> 16);
    p[3] = (uint8_t)(v >> 24);
}

static void duel_html_le16(uint8_t *p, uint16_t v)
{
    p[0] = (uint8_t)v;
    p[1] = (uint8_t)(v >> 8);
}

/* A side's network: shape, names, layers and the connections, or null. */
static int duel_html_net(FILE *f, const duel_replay_net *rn)
{
    duel_netgraph g;
    const nrt_net *n = &rn->shape;
    char buf[DUEL_NETGRAPH_NAME];
    unsigned v;
    uint32_t k;
    if (n->n_nodes == 0) {
        fputs("null", f);
        return 0;
    }
    if (duel_netgraph_build(&g, n) != 0)
        return -1;
    fprintf(f, "{\"inputs\":%u,\"outputs\":%u,\"hidden\":%u,\"names\":[", (unsigned)n->n_inputs, (unsigned)n->n_outputs,
            (unsigned)n->n_hidden);
    for (v = 0; v < n->n_nodes; v++) {
        if (v)
            fputc(',', f);
        duel_html_str(f, duel_netgraph_name(&g, v, buf));
    }
    fputs("],\"depth\":[", f);
    for (v = 0; v < n->n_nodes; v++)
        fprintf(f, "%s%d", v ? "," : "", g.depth[v]);
    fputs("],\"dead\":[", f);
    for (v = 0; v < n->n_nodes; v++)
        fprintf(f, "%s%d", v ? "," : "", v >= (unsigned)(n->n_inputs + n->n_outputs) ? g.dead[v] : 0);
    fputs("],\"conns\":[", f);
    for (k = 0; k < n->n_conns; k++)
        fprintf(f, "%s[%u,%u,%.6g]", k ? "," : "", (unsigned)n->src[k], (unsigned)g.dst[k], n->weight[k] / 4096.0);
    fputs("],\"recurrent\":[", f);
    for (k = 0; k < n->n_conns; k++)
        fprintf(f, "%s%d", k ? "," : "", g.recurrent[k]);
    fputs("]}", f);
    duel_netgraph_free(&g);
    return 0;
}

static const char *duel_html_step_name(const duel_replay *r, int s)
{
    if (r->net[s].shape.n_nodes != 0)
        return r->net[s].shape.step == NRT_STEP_PROPAGATE ? "propagate" : "sync";
    return duel_trace_step_name(r->step[s]);
}

int duel_html_duel_json(FILE *f, const duel_replay *r, const char *title)
{
    const size_t n = r->n;
    const duel_frame *last;
    uint8_t *pos, *food, *in, *out, *hid[2] = {NULL, NULL};
    const char *wname = duel_rules_name(&r->rules);
    size_t t;
    int s, i, first = 1, winner = -1;
    unsigned j;

    if (n == 0)
        return -1;
    last = &r->frames[n - 1];
    pos = (uint8_t *)malloc(n * 32);
    food = (uint8_t *)malloc(n * 4);
    in = (uint8_t *)malloc(n * 2 * DUEL_N_INPUTS * 2);
    out = (uint8_t *)malloc(n * 2 * DUEL_N_OUTPUTS * 2);
    for (s = 0; s < 2; s++)
        hid[s] = (uint8_t *)malloc(n * (size_t)r->net[s].shape.n_hidden * 2 + 1);
    if (pos == NULL || food == NULL || in == NULL || out == NULL || hid[0] == NULL || hid[1] == NULL) {
        free(pos), free(food), free(in), free(out), free(hid[0]), free(hid[1]);
        return -1;
    }
    for (t = 0; t < n; t++) {
        const duel_frame *fr = &r->frames[t];
        for (s = 0; s < 2; s++) {
            const duel_robot *rb = &fr->w.robot[s];
            duel_html_le32(pos + t * 32 + s * 16, (uint32_t)rb->x);
            duel_html_le32(pos + t * 32 + s * 16 + 4, (uint32_t)rb->y);
            duel_html_le32(pos + t * 32 + s * 16 + 8, rb->heading);
            duel_html_le32(pos + t * 32 + s * 16 + 12, (uint32_t)rb->energy);
            for (i = 0; i < DUEL_N_INPUTS; i++)
                duel_html_le16(in + (t * 2 * DUEL_N_INPUTS + (size_t)s * DUEL_N_INPUTS + (size_t)i) * 2,
                               (uint16_t)fr->in[s][i]);
            for (i = 0; i < DUEL_N_OUTPUTS; i++)
                duel_html_le16(out + (t * 2 * DUEL_N_OUTPUTS + (size_t)s * DUEL_N_OUTPUTS + (size_t)i) * 2,
                               (uint16_t)fr->out[s][i]);
            for (j = 0; j < r->net[s].shape.n_hidden; j++)
                duel_html_le16(hid[s] + (t * r->net[s].shape.n_hidden + j) * 2,
                               (uint16_t)r->net[s].hidden[t * r->net[s].shape.n_hidden + j]);
        }
        duel_html_le32(food + t * 4, fr->w.food_mask);
    }

    fputc('{', f);
    duel_html_common(f, "duel", title);
    fputs("\"world\":{\"name\":", f);
    duel_html_str(f, wname != NULL ? wname : "custom");
    fprintf(f, ",\"id\":\"%016llx\",\"radius\":%.6g,\"eat_dist\":%.6g,\"food_radius\":5,\"food_range\":%u,"
               "\"robot_range\":%u,\"start_energy\":%.6g,\"food_energy\":%.6g,\"board\":%d,\"max_steps\":%d},",
            (unsigned long long)duel_rules_id(&r->rules), r->rules.radius / 65536.0, r->rules.eat_dist / 65536.0,
            (unsigned)r->rules.food_range, (unsigned)r->rules.robot_range, r->rules.start_energy / 65536.0,
            r->rules.food_energy / 65536.0, DUEL_BOARD, DUEL_MAX_STEPS);
    fprintf(f, "\"food_config\":%d,\"food_xy\":[", r->food_config < 0 ? -1 : r->food_config);
    for (i = 0; i < r->frames[0].w.n_food; i++)
        fprintf(f, "%s%.6f,%.6f", i ? "," : "", r->frames[0].w.food_x[i] / 65536.0, r->frames[0].w.food_y[i] / 65536.0);
    fputs("],\"sides\":[", f);
    for (s = 0; s < 2; s++) {
        fputs(s ? ",{\"name\":" : "{\"name\":", f);
        duel_html_str(f, s ? r->east : r->west);
        fputs(",\"step\":", f);
        duel_html_str(f, duel_html_step_name(r, s));
        fputs(",\"net\":", f);
        if (duel_html_net(f, &r->net[s]) != 0) {
            free(pos), free(food), free(in), free(out), free(hid[0]), free(hid[1]);
            return -1;
        }
        fputc('}', f);
    }
    if (last->ev.outcome == DUEL_WEST_WINS)
        winner = 0;
    else if (last->ev.outcome == DUEL_EAST_WINS)
        winner = 1;
    fprintf(f, "],\"n\":%u,\"outcome\":", (unsigned)n);
    {
        char line[128];
        snprintf(line, sizeof line, "%s after %u steps", duel_outcome_text(last->ev.outcome), (unsigned)last->t);
        duel_html_str(f, line);
    }
    fprintf(f, ",\"winner\":%d,\"events\":[", winner);
    for (t = 0; t + 1 < n; t++) {
        const duel_event *ev = &r->frames[t].ev;
        for (s = 0; s < 2; s++)
            for (i = 0; i < DUEL_MAX_FOOD; i++)
                if (ev->eaten_by[s] & (1u << i)) {
                    fprintf(f, "%s[%u,\"eat\",%d,%d]", first ? "" : ",", (unsigned)r->frames[t].t, s, i);
                    first = 0;
                }
        if (ev->outcome == DUEL_WEST_WINS || ev->outcome == DUEL_EAST_WINS || ev->outcome == DUEL_DRAW) {
            fprintf(f, "%s[%u,\"collision\",%d]", first ? "" : ",", (unsigned)r->frames[t].t,
                    ev->outcome == DUEL_WEST_WINS ? 0 : ev->outcome == DUEL_EAST_WINS ? 1 : -1);
            first = 0;
        } else if (ev->outcome == DUEL_TIMEOUT) {
            fprintf(f, "%s[%u,\"timeout\"]", first ? "" : ",", (unsigned)r->frames[t].t);
            first = 0;
        }
    }
    fputs("],\"frames\":{\"pos\":", f);
    duel_html_b64(f, pos, n * 32);
    fputs(",\"food\":", f);
    duel_html_b64(f, food, n * 4);
    fputs(",\"in\":", f);
    duel_html_b64(f, in, n * 2 * DUEL_N_INPUTS * 2);
    fputs(",\"out\":", f);
    duel_html_b64(f, out, n * 2 * DUEL_N_OUTPUTS * 2);
    fputs(",\"hid\":[", f);
    duel_html_b64(f, hid[0], n * (size_t)r->net[0].shape.n_hidden * 2);
    fputc(',', f);
    duel_html_b64(f, hid[1], n * (size_t)r->net[1].shape.n_hidden * 2);
    fputs("]}}", f);
    free(pos), free(food), free(in), free(out), free(hid[0]), free(hid[1]);
    return 0;
}

int duel_html_duel_page(FILE *f, const duel_replay *r, const char *title)
{
    int err;
    duel_html_open(f);
    err = duel_html_duel_json(f, r, title);
    duel_html_close(f);
    return err;
}
