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
    l.m = size / 40;
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

/* Seven-segment digits: bit 0 = top (a), then b (top right), c, d (bottom),
 * e, f (top left), g (middle). */
static const uint8_t duel_rd_segments[10] = {0x3f, 0x06, 0x5b, 0x4f, 0x66, 0x6d, 0x7d, 0x07, 0x7f, 0x6f};

static void duel_rd_digit(int d, double x, double y, double h)
{
    double w = 0.55 * h, th = 0.14 * h, m = y + h / 2;
    unsigned s = duel_rd_segments[d];
    if (s & 0x01) duel_rd_rect(x, y, x + w, y + th);
    if (s & 0x02) duel_rd_rect(x + w - th, y, x + w, m + th / 2);
    if (s & 0x04) duel_rd_rect(x + w - th, m - th / 2, x + w, y + h);
    if (s & 0x08) duel_rd_rect(x, y + h - th, x + w, y + h);
    if (s & 0x10) duel_rd_rect(x, m - th / 2, x + th, y + h);
    if (s & 0x20) duel_rd_rect(x, y, x + th, m + th / 2);
    if (s & 0x40) duel_rd_rect(x, m - th / 2, x + w, m + th / 2);
}

/* n in digits of height h, centred on (cx, cy). */
static void duel_rd_number(unsigned n, double cx, double cy, double h)
{
    char s[16];
    int len = snprintf(s, sizeof s, "%u", n), i;
    double adv = 0.8 * h, w = adv * (len - 1) + 0.55 * h, x = cx - w / 2;
    for (i = 0; i < len; i++)
        duel_rd_digit(s[i] - '0', x + i * adv, cy - h / 2, h);
}

static double duel_rd_clamp01(double v)
{
    return v < 0 ? 0 : (v > 1 ? 1 : v);
}

/* One robot's energy bar: the frame, the empty bar, the fill in the robot's
 * colour growing from the outer end (west: left, east: right), a tick at the
 * start energy. Full scale: the start energy plus every food item. */
static void duel_rd_energy_bar(const duel_rd_layout *l, int side, double energy, double full)
{
    double len = 0.36 * l->b, h = 0.34 * l->hud, y0 = (l->hud - h) / 2, inset = 1.0;
    double x0 = side == DUEL_WEST ? l->ox : l->ox + l->b - len, x1 = x0 + len;
    double in0 = x0 + inset, in1 = x1 - inset, fill = (in1 - in0) * duel_rd_clamp01(energy / full);
    double tick = (in1 - in0) * DUEL_START_ENERGY / full;
    duel_rd_colour(DUEL_RGB_BAR_EDGE);
    duel_rd_rect(x0, y0, x1, y0 + h);
    duel_rd_colour(DUEL_RGB_BAR_EMPTY);
    duel_rd_rect(in0, y0 + inset, in1, y0 + h - inset);
    duel_rd_colour(side == DUEL_WEST ? DUEL_RGB_WEST : DUEL_RGB_EAST);
    if (side == DUEL_WEST)
        duel_rd_rect(in0, y0 + inset, in0 + fill, y0 + h - inset);
    else
        duel_rd_rect(in1 - fill, y0 + inset, in1, y0 + h - inset);
    duel_rd_colour(DUEL_RGB_TICK);
    if (side == DUEL_WEST)
        duel_rd_rect(in0 + tick - 0.5, y0, in0 + tick + 0.5, y0 + h);
    else
        duel_rd_rect(in1 - tick - 0.5, y0, in1 - tick + 0.5, y0 + h);
}

static double duel_rd_heading(duel_angle a)
{
    return a * (2 * duel_rd_pi / 4294967296.0);
}

/* The five rangefinder sector boundaries, at heading + (2k+1) * 36 degrees,
 * from the robot's rim to the board's edge (the scissor), the robot's colour
 * at 40 % over the board. */
static void duel_rd_sensors(const duel_render *r, const duel_robot *rb, uint32_t colour, double k)
{
    double px, py, a0 = duel_rd_heading(rb->heading), reach = 900 * k;
    int i;
    duel_render_to_pixel(r->size, rb->x / 65536.0, rb->y / 65536.0, &px, &py);
    glColor4ub((GLubyte)(colour >> 16), (GLubyte)(colour >> 8), (GLubyte)colour, 128);
    for (i = 0; i < 5; i++) {
        double a = a0 + (2 * i + 1) * duel_rd_pi / 5, c = cos(a), s = -sin(a); /* y down */
        duel_rd_stroke(px + c * DUEL_RADIUS * k, py + s * DUEL_RADIUS * k, px + c * reach, py + s * reach, 1.0);
    }
}

/* A robot: a disc of radius 10 units with a dark outline, and a white
 * triangle pointing along the heading that leaves the centre in the robot's
 * colour. */
static void duel_rd_robot(const duel_render *r, const duel_robot *rb, uint32_t colour, double k)
{
    double px, py, a = duel_rd_heading(rb->heading), c = cos(a), s = -sin(a), rad = DUEL_RADIUS * k;
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
    duel_rd_layout l = duel_rd_layout_of(r->size);
    int w = r->size * DUEL_RENDER_SS, side, i;
    double k = (double)l.b / DUEL_BOARD, full = DUEL_START_ENERGY + DUEL_FOOD_ENERGY * (double)f->w.n_food;
    uint32_t digits = DUEL_RGB_DIGITS;

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
            duel_rd_sensors(r, &f->w.robot[side], side == DUEL_WEST ? DUEL_RGB_WEST : DUEL_RGB_EAST, k);
        glDisable(GL_BLEND);
        glDisable(GL_SCISSOR_TEST);
    }
    for (side = 0; side < 2; side++)
        duel_rd_robot(r, &f->w.robot[side], side == DUEL_WEST ? DUEL_RGB_WEST : DUEL_RGB_EAST, k);

    for (side = 0; side < 2; side++)
        duel_rd_energy_bar(&l, side, f->w.robot[side].energy / 65536.0, full);
    if (f->ev.outcome == DUEL_WEST_WINS)
        digits = DUEL_RGB_WEST;
    else if (f->ev.outcome == DUEL_EAST_WINS)
        digits = DUEL_RGB_EAST;
    duel_rd_colour(digits);
    duel_rd_number(f->t, r->size / 2.0, l.hud / 2.0, 0.5 * l.hud);

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
