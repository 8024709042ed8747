/* duel_render.c - a duel frame drawn with legacy OpenGL into an OSMesa off-screen buffer, averaged down and written as PNG with libpng. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <GL/osmesa.h>
#include <png.h>

#include "duel_files.h"
#include "duel_font.h"
#include "duel_render.h"

static const double duel_rd_pi = 3.14159265358979323846;

/* The layout of an image of side size, in pixels of the final image. */
typedef struct duel_rd_layout {
    int hud;      /* the strip at the top */
    int m;        /* the margin below the board */
    int b;        /* the board's side */
    int ox;       /* the board's left edge */
} duel_rd_layout;

static duel_rd_layout duel_rd_layout_of(int size)
{
    duel_rd_layout l;
    l.hud = size * 3 / 40;
    l.m = size / 30;
    l.b = size - l.hud - l.m;
    l.ox = (size - l.b) / 2;
    return l;
}

void duel_render_to_pixel(int size, double x, double y, double *px, double *py)
{
    duel_rd_layout l = duel_rd_layout_of(size);
    *px = l.ox + x * l.b / DUEL_BOARD;
    *py = l.hud + (DUEL_BOARD - y) * l.b / DUEL_BOARD;
}

int duel_render_open(duel_render *r, int size, char *err, size_t err_len)
{
    int w = size * DUEL_RENDER_SS;
    memset(r, 0, sizeof *r);
    if (size < DUEL_RENDER_MIN_SIZE || size > DUEL_RENDER_MAX_SIZE) {
        snprintf(err, err_len, "image size %d out of range (%d..%d)", size, DUEL_RENDER_MIN_SIZE,
                 DUEL_RENDER_MAX_SIZE);
        return -1;
    }
    r->size = size;
    r->buf = (uint8_t *)calloc((size_t)w * (size_t)w, 4);
    r->rgb = (uint8_t *)calloc((size_t)size * (size_t)size, 3);
    if (r->buf == NULL || r->rgb == NULL) {
        snprintf(err, err_len, "out of memory for %dx%d images", size, size);
        duel_render_close(r);
        return -1;
    }
    /* RGBA, no depth, stencil or accumulation buffer: shapes are drawn in order */
    r->ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    if (r->ctx == NULL) {
        snprintf(err, err_len, "cannot create an OSMesa (off-screen OpenGL) context");
        duel_render_close(r);
        return -1;
    }
    if (!OSMesaMakeCurrent((OSMesaContext)r->ctx, r->buf, GL_UNSIGNED_BYTE, w, w)) {
        snprintf(err, err_len, "cannot bind the OSMesa context to a %dx%d buffer", w, w);
        duel_render_close(r);
        return -1;
    }
    return 0;
}

void duel_render_close(duel_render *r)
{
    if (r->ctx != NULL)
        OSMesaDestroyContext((OSMesaContext)r->ctx);
    free(r->buf);
    free(r->rgb);
    memset(r, 0, sizeof *r);
}

/* ---- drawing, in the final image's pixel coordinates (y down) ----------- */

static void duel_rd_colour(uint32_t c)
{
    glColor4ub((GLubyte)(c >> 16), (GLubyte)(c >> 8), (GLubyte)c, 255);
}

static void duel_rd_rect(double x0, double y0, double x1, double y1)
{
    glBegin(GL_QUADS);
    glVertex2d(x0, y0);
    glVertex2d(x1, y0);
    glVertex2d(x1, y1);
    glVertex2d(x0, y1);
    glEnd();
}

static void duel_rd_disc(double cx, double cy, double rad)
{
    enum { N = 64 };
    int i;
    glBegin(GL_TRIANGLE_FAN);
    glVertex2d(cx, cy);
    for (i = 0; i <= N; i++) {
        double a = 2 * duel_rd_pi * (i % N) / N;
        glVertex2d(cx + rad * cos(a), cy + rad * sin(a));
    }
    glEnd();
}

/* A straight stroke of width wd as a quad (no dependence on line widths). */
static void duel_rd_stroke(double x0, double y0, double x1, double y1, double wd)
{
    double dx = x1 - x0, dy = y1 - y0, len = sqrt(dx * dx + dy * dy), nx, ny;
    if (len <= 0)
        return;
    nx = -dy / len * wd / 2;
    ny = dx / len * wd / 2;
    glBegin(GL_QUADS);
    glVertex2d(x0 + nx, y0 + ny);
    glVertex2d(x1 + nx, y1 + ny);
    glVertex2d(x1 - nx, y1 - ny);
    glVertex2d(x0 - nx, y0 - ny);
    glEnd();
}

/* The font's dot at image side size: size / 400 rounded down to a half
 * pixel (one sample of the 2 x 2), at least a half. */
static double duel_rd_dot(int size)
{
    int halves = size / 200;
    return (halves < 1 ? 1 : halves) * 0.5;
}

void duel_render_geom_of(int size, duel_render_geom *g)
{
    duel_rd_layout l = duel_rd_layout_of(size);
    double dot = duel_rd_dot(size), adv = DUEL_FONT_ADV * dot, gap = 3 * dot, wide = 3 * adv, bar_h = 8 * dot;
    /* the bar row across the board's width: bar, number, "step 750", number,
     * bar; three characters between a number and the step, so they do not
     * read as one line */
    double num_w = 4 * adv, step_w = duel_render_text_width("step 750", dot);
    double len = (l.b - step_w - 2 * num_w - 2 * gap - 2 * wide) / 2;
    g->hud = l.hud;
    g->m = l.m;
    g->b = l.b;
    g->ox = l.ox;
    g->dot = dot;
    g->legend_y = 0.30 * l.hud;
    g->bar_y0 = 0.72 * l.hud - bar_h / 2;
    g->bar_y1 = g->bar_y0 + bar_h;
    g->bar_x0[DUEL_WEST] = l.ox;
    g->bar_x1[DUEL_WEST] = l.ox + len;
    g->num_x0[DUEL_WEST] = l.ox + len + gap;
    g->num_x1[DUEL_WEST] = g->num_x0[DUEL_WEST] + num_w;
    g->bar_x1[DUEL_EAST] = l.ox + l.b;
    g->bar_x0[DUEL_EAST] = l.ox + l.b - len;
    g->num_x1[DUEL_EAST] = l.ox + l.b - len - gap;
    g->num_x0[DUEL_EAST] = g->num_x1[DUEL_EAST] - num_w;
    g->bottom_y = l.hud + l.b + l.m / 2.0;
}

double duel_render_text_width(const char *s, double dot)
{
    size_t n = strlen(s);
    return n == 0 ? 0 : ((double)n * DUEL_FONT_ADV - 1) * dot;
}

/* s with its top-left corner at (x, y), a rectangle per run of set dots. */
static void duel_rd_text(const char *s, double x, double y, double dot)
{
    for (; *s != '\0'; s++, x += DUEL_FONT_ADV * dot) {
        const uint8_t *g = duel_font_glyph(*s);
        double gy = y + duel_font_drop(*s) * dot;
        int row, col;
        for (row = 0; row < DUEL_FONT_H; row++)
            for (col = 0; col < DUEL_FONT_W; col++) {
                int end = col;
                if (!(g[row] >> (DUEL_FONT_W - 1 - col) & 1))
                    continue;
                while (end + 1 < DUEL_FONT_W && (g[row] >> (DUEL_FONT_W - 2 - end) & 1))
                    end++;
                duel_rd_rect(x + col * dot, gy + row * dot, x + (end + 1) * dot, gy + (row + 1) * dot);
                col = end;
            }
    }
}

/* Text placed on the centre line cy: align < 0 starting at x, 0 centred
 * on x, > 0 ending at x. */
static void duel_rd_text_at(const char *s, double x, double cy, int align, double dot)
{
    double w = duel_render_text_width(s, dot), y = cy - DUEL_FONT_H * dot / 2;
    duel_rd_text(s, align < 0 ? x : (align == 0 ? x - w / 2 : x - w), y, dot);
}

/* name shortened to at most max characters: its start replaced by an
 * ellipsis, since a path's end (the file) says most; a path is cut at a
 * '/' where that fits ("…/gen-00127.blob"). */
static void duel_rd_fit(char *out, size_t out_len, const char *name, int max)
{
    size_t n = strlen(name), keep, at = 0, i;
    if (max < 2)
        max = 2;
    if (n <= (size_t)max) {
        snprintf(out, out_len, "%s", name);
        return;
    }
    keep = (size_t)max - 1;
    for (i = 0; i < n; i++)
        if (name[i] == '/' && n - i <= keep) {
            keep = n - i;
            break;
        }
    if (keep + 2 > out_len)
        keep = out_len - 2;
    out[at++] = DUEL_FONT_ELLIPSIS;
    memcpy(out + at, name + n - keep, keep);
    out[at + keep] = '\0';
}

/* The shortest a name is shortened to before its last path component is
 * cut: "…/BASENAME" for a path, else 8 characters. */
static int duel_rd_short_len(const char *name)
{
    const char *slash = strrchr(name, '/');
    int n = (int)strlen(name);
    if (slash != NULL)
        return 1 + (int)strlen(slash);
    return n < 8 ? n : 8;
}

static double duel_rd_clamp01(double v)
{
    return v < 0 ? 0 : (v > 1 ? 1 : v);
}

/* One robot's energy bar: the frame, the empty bar, the fill in the robot's
 * colour growing from the outer end (west: left, east: right), a tick at the
 * start energy; its number beside it, on the inner side. Full scale: the
 * start energy plus every food item. */
static void duel_rd_energy_bar(const duel_render_geom *g, int side, double energy, double full, double start)
{
    double x0 = g->bar_x0[side], x1 = g->bar_x1[side], y0 = g->bar_y0, y1 = g->bar_y1, inset = 1.0;
    double in0 = x0 + inset, in1 = x1 - inset, fill = (in1 - in0) * duel_rd_clamp01(energy / full);
    double tick = (in1 - in0) * start / full, cy = (y0 + y1) / 2;
    char num[16];
    duel_rd_colour(DUEL_RGB_BAR_EDGE);
    duel_rd_rect(x0, y0, x1, y1);
    duel_rd_colour(DUEL_RGB_BAR_EMPTY);
    duel_rd_rect(in0, y0 + inset, in1, y1 - inset);
    duel_rd_colour(side == DUEL_WEST ? DUEL_RGB_WEST : DUEL_RGB_EAST);
    if (side == DUEL_WEST)
        duel_rd_rect(in0, y0 + inset, in0 + fill, y1 - inset);
    else
        duel_rd_rect(in1 - fill, y0 + inset, in1, y1 - inset);
    duel_rd_colour(DUEL_RGB_TICK);
    if (side == DUEL_WEST)
        duel_rd_rect(in0 + tick - 0.5, y0, in0 + tick + 0.5, y1);
    else
        duel_rd_rect(in1 - tick - 0.5, y0, in1 - tick + 0.5, y1);
    /* whole units, rounded down: 1200 at the start, 0 when empty */
    snprintf(num, sizeof num, "%.0f", floor(energy < 0 ? 0 : energy));
    duel_rd_colour(DUEL_RGB_TEXT);
    if (side == DUEL_WEST)
        duel_rd_text_at(num, g->num_x0[side], cy, -1, g->dot);
    else
        duel_rd_text_at(num, g->num_x1[side], cy, 1, g->dot);
}

/* The legend row: a disc in each side's colour, "west: NAME" from the
 * left and "east: NAME" from the right; names that do not fit both lose
 * their start, the longer one first. */
static void duel_rd_legend(const duel_render_geom *g, const char *west, const char *east)
{
    double dot = g->dot, rad = 3.5 * dot, adv = DUEL_FONT_ADV * dot;
    int room = (int)((g->b - 4 * rad - 6 * dot) / adv) - 2 * 6 - 3; /* "west: ", "east: ", three apart */
    int nw = (int)strlen(west), ne = (int)strlen(east), mw = nw, me = ne;
    char fit[300], line[320];
    if (nw + ne > room) {
        /* the longer loses first: cut to its file name if the other then fits whole */
        int half = room / 2;
        if (nw <= half || (ne >= nw && nw + duel_rd_short_len(east) <= room))
            me = room - nw;
        else if (ne <= half || nw + duel_rd_short_len(west) <= room)
            mw = room - ne;
        else
            mw = me = half;
    }
    duel_rd_colour(DUEL_RGB_WEST);
    duel_rd_disc(g->ox + rad, g->legend_y, rad);
    duel_rd_colour(DUEL_RGB_EAST);
    duel_rd_disc(g->ox + g->b - rad, g->legend_y, rad);
    duel_rd_colour(DUEL_RGB_TEXT);
    duel_rd_fit(fit, sizeof fit, west, mw);
    snprintf(line, sizeof line, "west: %s", fit);
    duel_rd_text_at(line, g->ox + 2 * rad + 3 * dot, g->legend_y, -1, dot);
    duel_rd_fit(fit, sizeof fit, east, me);
    snprintf(line, sizeof line, "east: %s", fit);
    duel_rd_text_at(line, g->ox + g->b - 2 * rad - 3 * dot, g->legend_y, 1, dot);
}

/* Each robot's path so far: a stroke through its centres in frames
 * 0..n-1, in its colour half way to the board's, under the robots. */
static void duel_rd_trails(const duel_render *r, const duel_frame *trail, size_t n, double rad)
{
    double wd = 0.25 * rad;
    size_t i;
    int side;
    if (wd < 1)
        wd = 1;
    for (side = 0; side < 2; side++) {
        duel_rd_colour(side == DUEL_WEST ? DUEL_RGB_TRAIL_WEST : DUEL_RGB_TRAIL_EAST);
        for (i = 1; i < n; i++) {
            const duel_robot *a = &trail[i - 1].w.robot[side], *b = &trail[i].w.robot[side];
            double x0, y0, x1, y1, dx, dy, len;
            duel_render_to_pixel(r->size, a->x / 65536.0, a->y / 65536.0, &x0, &y0);
            duel_render_to_pixel(r->size, b->x / 65536.0, b->y / 65536.0, &x1, &y1);
            dx = x1 - x0;
            dy = y1 - y0;
            len = sqrt(dx * dx + dy * dy);
            if (len <= 0)
                continue;
            /* each piece reaches half the width past both ends: no notch at a turn */
            dx *= wd / 2 / len;
            dy *= wd / 2 / len;
            duel_rd_stroke(x0 - dx, y0 - dy, x1 + dx, y1 + dy, wd);
        }
    }
}

static double duel_rd_heading(duel_angle a)
{
    return a * (2 * duel_rd_pi / 4294967296.0);
}

/* The five rangefinder sector boundaries, at heading + (2k+1) * 36 degrees,
 * from the robot's rim to the board's edge (the scissor), the robot's colour
 * at 40 % over the board. */
static void duel_rd_sensors(const duel_render *r, const duel_robot *rb, uint32_t colour, double k, double rad)
{
    double px, py, a0 = duel_rd_heading(rb->heading), reach = 900 * k;
    int i;
    duel_render_to_pixel(r->size, rb->x / 65536.0, rb->y / 65536.0, &px, &py);
    glColor4ub((GLubyte)(colour >> 16), (GLubyte)(colour >> 8), (GLubyte)colour, 128);
    for (i = 0; i < 5; i++) {
        double a = a0 + (2 * i + 1) * duel_rd_pi / 5, c = cos(a), s = -sin(a); /* y down */
        duel_rd_stroke(px + c * rad, py + s * rad, px + c * reach, py + s * reach, 1.0);
    }
}

/* A robot: a disc of the world's radius (rad pixels: 10 units in v1) with
 * a dark outline, and a white triangle pointing along the heading that
 * leaves the centre in the robot's colour. */
static void duel_rd_robot(const duel_render *r, const duel_robot *rb, uint32_t colour, double rad)
{
    double px, py, a = duel_rd_heading(rb->heading), c = cos(a), s = -sin(a);
    double outline = 0.1 * rad < 0.75 ? 0.75 : 0.1 * rad;
    duel_render_to_pixel(r->size, rb->x / 65536.0, rb->y / 65536.0, &px, &py);
    duel_rd_colour(DUEL_RGB_OUTLINE);
    duel_rd_disc(px, py, rad);
    duel_rd_colour(colour);
    duel_rd_disc(px, py, rad - outline);
    duel_rd_colour(DUEL_RGB_NOSE);
    glBegin(GL_TRIANGLES);
    glVertex2d(px + c * 0.9 * rad, py + s * 0.9 * rad);
    glVertex2d(px + c * 0.2 * rad - s * 0.45 * rad, py + s * 0.2 * rad + c * 0.45 * rad);
    glVertex2d(px + c * 0.2 * rad + s * 0.45 * rad, py + s * 0.2 * rad - c * 0.45 * rad);
    glEnd();
}

/* Averages the 2 x 2 samples of each pixel into rgb (rounded), flipping the
 * rows (OpenGL's are bottom-up). */
#if DUEL_RENDER_SS != 2
#error "duel_rd_downsample averages 2 x 2 samples"
#endif
static void duel_rd_downsample(duel_render *r)
{
    size_t n = (size_t)r->size, w = n * DUEL_RENDER_SS, x, y;
    uint8_t *out = r->rgb;
    for (y = 0; y < n; y++) {
        /* image row y: OpenGL rows w - 1 - 2y and w - 2 - 2y */
        const uint8_t *a = r->buf + (w - 1 - 2 * y) * w * 4, *b = a - w * 4;
        for (x = 0; x < n; x++, a += 8, b += 8, out += 3) {
            out[0] = (uint8_t)((a[0] + a[4] + b[0] + b[4] + 2) >> 2);
            out[1] = (uint8_t)((a[1] + a[5] + b[1] + b[5] + 2) >> 2);
            out[2] = (uint8_t)((a[2] + a[6] + b[2] + b[6] + 2) >> 2);
        }
    }
}

void duel_render_frame(duel_render *r, const duel_frame *f, unsigned flags)
{
    duel_render_frame_info(r, f, flags, NULL);
}

void duel_render_frame_info(duel_render *r, const duel_frame *f, unsigned flags, const duel_render_info *info)
{
    duel_rd_layout l = duel_rd_layout_of(r->size);
    duel_render_geom g;
    int w = r->size * DUEL_RENDER_SS, side, i;
    /* the frame's world: its robots' size, start energy and food (v1 for a world without rules) */
    const duel_rules *rules = f->w.rules != NULL ? f->w.rules : duel_rules_v1();
    double k = (double)l.b / DUEL_BOARD, start = rules->start_energy / 65536.0;
    double full = start + rules->food_energy / 65536.0 * (double)f->w.n_food, robot = rules->radius / 65536.0 * k;
    char line[96];

    duel_render_geom_of(r->size, &g);
    glViewport(0, 0, w, w);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, r->size, r->size, 0, -1, 1); /* final-image pixels, y down */
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_DITHER);
    glShadeModel(GL_FLAT);
    glClearColor((DUEL_RGB_FRAME >> 16) / 255.0f, ((DUEL_RGB_FRAME >> 8) & 255) / 255.0f,
                 (DUEL_RGB_FRAME & 255) / 255.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);

    /* the board, its edge line just outside it */
    duel_rd_colour(DUEL_RGB_EDGE);
    duel_rd_rect(l.ox - 1, l.hud - 1, l.ox + l.b + 1, l.hud + l.b + 1);
    duel_rd_colour(DUEL_RGB_BOARD);
    duel_rd_rect(l.ox, l.hud, l.ox + l.b, l.hud + l.b);

    if ((flags & DUEL_RENDER_TRAILS) && info != NULL && info->trail != NULL)
        duel_rd_trails(r, info->trail, info->n_trail, robot);

    duel_rd_colour(DUEL_RGB_FOOD);
    for (i = 0; i < f->w.n_food && i < DUEL_MAX_FOOD; i++)
        if (f->w.food_mask & (1u << i)) {
            double px, py;
            duel_render_to_pixel(r->size, f->w.food_x[i] / 65536.0, f->w.food_y[i] / 65536.0, &px, &py);
            duel_rd_disc(px, py, DUEL_FOOD_DRAW_RADIUS * k);
        }

    if (flags & DUEL_RENDER_SENSORS) {
        glEnable(GL_SCISSOR_TEST);
        glScissor(l.ox * DUEL_RENDER_SS, l.m * DUEL_RENDER_SS, l.b * DUEL_RENDER_SS, l.b * DUEL_RENDER_SS);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        for (side = 0; side < 2; side++)
            duel_rd_sensors(r, &f->w.robot[side], side == DUEL_WEST ? DUEL_RGB_WEST : DUEL_RGB_EAST, k, robot);
        glDisable(GL_BLEND);
        glDisable(GL_SCISSOR_TEST);
    }
    for (side = 0; side < 2; side++)
        duel_rd_robot(r, &f->w.robot[side], side == DUEL_WEST ? DUEL_RGB_WEST : DUEL_RGB_EAST, robot);

    /* the top strip: legend, bars with their numbers, the step */
    if (info != NULL && info->west != NULL && info->east != NULL)
        duel_rd_legend(&g, info->west, info->east);
    for (side = 0; side < 2; side++)
        duel_rd_energy_bar(&g, side, f->w.robot[side].energy / 65536.0, full, start);
    duel_rd_colour(DUEL_RGB_TEXT);
    snprintf(line, sizeof line, "step %u", (unsigned)f->t);
    duel_rd_text_at(line, r->size / 2.0, (g.bar_y0 + g.bar_y1) / 2, 0, g.dot);

    /* the bottom strip: the outcome on the last frame (the winner's colour), the food before */
    if (f->ev.outcome != DUEL_RUNNING) {
        uint32_t c = f->ev.outcome == DUEL_WEST_WINS ? DUEL_RGB_WEST
                     : f->ev.outcome == DUEL_EAST_WINS ? DUEL_RGB_EAST : DUEL_RGB_TEXT;
        double tw, rad = 3.5 * g.dot;
        snprintf(line, sizeof line, "%s after %u steps", duel_outcome_text(f->ev.outcome), (unsigned)f->t);
        tw = duel_render_text_width(line, g.dot);
        /* light text on the dark strip, the winner's colour as a disc before it (blue text would be dim) */
        duel_rd_colour(c);
        duel_rd_disc(r->size / 2.0 - tw / 2 - 4 * g.dot - rad, g.bottom_y, rad);
        duel_rd_colour(DUEL_RGB_TEXT);
        duel_rd_text_at(line, r->size / 2.0, g.bottom_y, 0, g.dot);
    } else if (info != NULL && info->food_config != DUEL_RENDER_NO_FOOD) {
        if (info->food_config == DUEL_TRAINING)
            snprintf(line, sizeof line, "training food");
        else
            snprintf(line, sizeof line, "food configuration %d", info->food_config);
        duel_rd_colour(DUEL_RGB_TEXT_DIM);
        duel_rd_text_at(line, g.ox, g.bottom_y, -1, g.dot);
    }

    glFinish();
    duel_rd_downsample(r);
}

/* ---- PNG ------------------------------------------------------------------ */

/* libpng reports errors through these: the message is kept, nothing printed. */
typedef struct duel_rd_png_err {
    jmp_buf jmp;
    char msg[160];
} duel_rd_png_err;

static void duel_rd_png_error(png_structp png, png_const_charp msg)
{
    duel_rd_png_err *e = (duel_rd_png_err *)png_get_error_ptr(png);
    snprintf(e->msg, sizeof e->msg, "%s", msg);
    longjmp(e->jmp, 1);
}

static void duel_rd_png_warning(png_structp png, png_const_charp msg)
{
    (void)png;
    (void)msg;
}

/* Encodes rgb into f. 0, or -1 with the reason in e->msg. */
static int duel_rd_png_encode(FILE *f, const uint8_t *rgb, int n, duel_rd_png_err *e)
{
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, e, duel_rd_png_error, duel_rd_png_warning);
    png_infop info = png != NULL ? png_create_info_struct(png) : NULL;
    int y;
    if (info == NULL) {
        png_destroy_write_struct(&png, NULL);
        snprintf(e->msg, sizeof e->msg, "out of memory");
        return -1;
    }
    /* png and info are not modified after this point, so longjmp keeps them */
    if (setjmp(e->jmp)) {
        png_destroy_write_struct(&png, &info);
        return -1;
    }
    png_init_io(png, f);
    png_set_compression_level(png, 6);
    /* flat colours: no row filter compresses as well as the adaptive one, at less than half the time */
    png_set_filter(png, 0, PNG_FILTER_NONE);
    png_set_IHDR(png, info, (png_uint_32)n, (png_uint_32)n, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    {
        /* what makes a later render replace this frame and refuse anybody else's file (duel_outputs.h) */
        png_text t;
        memset(&t, 0, sizeof t);
        t.compression = PNG_TEXT_COMPRESSION_NONE;
        t.key = (png_charp) "Software";
        t.text = (png_charp) "duel_evolve render";
        png_set_text(png, info, &t, 1);
    }
    png_write_info(png, info);
    for (y = 0; y < n; y++)
        png_write_row(png, rgb + (size_t)y * (size_t)n * 3);
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return 0;
}

int duel_render_write_png(const duel_render *r, const char *path, char *err, size_t err_len)
{
    size_t len = strlen(path) + sizeof ".tmp"; /* duel_files.h: PATH.tmp, taken over by the next write of PATH */
    char *tmp = (char *)malloc(len);
    duel_rd_png_err e;
    FILE *f = NULL;
    int fd, rc;

    if (tmp == NULL) {
        snprintf(err, err_len, "%s: out of memory", path);
        return -1;
    }
    snprintf(tmp, len, "%s.tmp", path);
    fd = duel_tmp_create(tmp);
    if (fd < 0 || (f = fdopen(fd, "wb")) == NULL) {
        snprintf(err, err_len, "%s: cannot write: %s", path, strerror(errno));
        if (fd >= 0) {
            close(fd);
            remove(tmp);
        }
        free(tmp);
        return -1;
    }
    e.msg[0] = '\0';
    rc = duel_rd_png_encode(f, r->rgb, r->size, &e);
    if (rc == 0 && ferror(f)) {
        snprintf(e.msg, sizeof e.msg, "%s", strerror(errno));
        rc = -1;
    }
    if (fclose(f) != 0 && rc == 0) {
        snprintf(e.msg, sizeof e.msg, "%s", strerror(errno));
        rc = -1;
    }
    if (rc == 0 && duel_file_commit(tmp, path) != 0) {
        snprintf(e.msg, sizeof e.msg, "%s", strerror(errno));
        rc = -1;
    }
    if (rc != 0) {
        snprintf(err, err_len, "%s: write failed: %s", path, e.msg);
        remove(tmp);
    }
    free(tmp);
    return rc;
}
