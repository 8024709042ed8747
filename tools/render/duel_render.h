/* duel_render.h - one duel frame drawn with OpenGL into an OSMesa off-screen buffer (no display), and written as PNG. */
/* tools/render/: replays, frames, videos and network pictures: a game as frames, drawn with OSMesa and written with libpng, ffmpeg and Graphviz run as programs (docs/render.md). */
#ifndef DUEL_RENDER_H
#define DUEL_RENDER_H

#include <stddef.h>
#include <stdint.h>

#include "duel_replay.h"

/*
 * The picture (docs/render.md): a square image of size x size pixels; a
 * strip of hud = 3 * size / 40 pixels at the top (the legend: each side's
 * colour and controller; energy bars with their numbers, the step), a strip
 * of m = size / 30 below the board (the food configuration, the outcome on
 * the last frame), and the 600 x 600 board as a square of side
 * b = size - hud - m at ox = (size - b) / 2 from the left (integer
 * divisions; size 600: hud 45, m 20, b 535, ox 32, 0.89 pixel per unit).
 * Board position (x, y), y up, is at image pixel coordinates (origin the
 * image's top-left corner, y down)
 *     px = ox + x * b / 600,   py = hud + (600 - y) * b / 600
 * and pixel (i, j) covers [i, i+1) x [j, j+1). Drawn at 2 x 2 samples per
 * pixel and averaged, so edges are smooth and the inside of a shape has its
 * colour exactly.
 */
#define DUEL_RENDER_MIN_SIZE 64
#define DUEL_RENDER_MAX_SIZE 2048
#define DUEL_RENDER_SS 2 /* samples per pixel along each axis */

/* Colours, 0xRRGGBB. */
#define DUEL_RGB_FRAME 0x1e2227u    /* around the board, the strip */
#define DUEL_RGB_BOARD 0xf4f1e8u    /* the board */
#define DUEL_RGB_EDGE 0x9a968cu     /* the board's edge line */
#define DUEL_RGB_FOOD 0x2ca02cu     /* food items still on the board */
#define DUEL_RGB_WEST 0x1f77b4u     /* the robot that started west: blue */
#define DUEL_RGB_EAST 0xff7f0eu     /* the robot that started east: orange */
#define DUEL_RGB_OUTLINE 0x202020u  /* robots' outline */
#define DUEL_RGB_NOSE 0xffffffu     /* heading mark */
#define DUEL_RGB_BAR_EDGE 0x8a9099u /* energy bar frame */
#define DUEL_RGB_BAR_EMPTY 0x30353cu
#define DUEL_RGB_TICK 0xffffffu     /* start energy on the bar */
#define DUEL_RGB_TEXT 0xe8e8e8u     /* the legend, the numbers, the step */
#define DUEL_RGB_TEXT_DIM 0x9aa0a8u /* the food configuration */
#define DUEL_RGB_TRAIL_WEST 0x89b4ceu /* the trails: the robot's colour half way to the board's */
#define DUEL_RGB_TRAIL_EAST 0xf9b87bu

#define DUEL_FOOD_DRAW_RADIUS 5 /* board units */

/* flags */
#define DUEL_RENDER_SENSORS 1u /* the rangefinder sector boundaries */
#define DUEL_RENDER_TRAILS 2u  /* the path of each robot's centre so far (duel_render_info.trail) */

/* Where things are in an image of side size, pixels from the top-left
 * corner (duel_render_geom_of): the tests read pixels there. Text is drawn
 * in dots of dot pixels (size / 400 rounded down to a half pixel, at least
 * a half: 1.5 at 600), a glyph 5 x 7 dots, a character 6 dots wide. */
typedef struct duel_render_geom {
    int hud, m, b, ox;       /* as above */
    double dot;              /* the font's dot */
    double legend_y;         /* the legend row's centre line (top strip) */
    double bar_y0, bar_y1;   /* the energy bars' row */
    double bar_x0[2], bar_x1[2]; /* each side's bar, frame included */
    double num_x0[2], num_x1[2]; /* each side's energy number */
    double bottom_y;         /* the bottom strip's centre line */
} duel_render_geom;

void duel_render_geom_of(int size, duel_render_geom *g);

/* What a frame shows besides the world. NULL fields: not drawn. */
typedef struct duel_render_info {
    const char *west, *east;  /* the controllers' names: the legend */
    int food_config;          /* DUEL_TRAINING or 0..DUEL_CONFIGS-1; DUEL_RENDER_NO_FOOD: not shown */
    const duel_frame *trail;  /* with DUEL_RENDER_TRAILS: frames 0..n_trail-1 (this one the last) */
    size_t n_trail;
} duel_render_info;
#define DUEL_RENDER_NO_FOOD (-1000)

typedef struct duel_render {
    int size;      /* the image's side, pixels */
    void *ctx;     /* OSMesaContext */
    uint8_t *buf;  /* (size * SS)^2 RGBA, rows bottom-up: what OpenGL draws into */
    uint8_t *rgb;  /* size^2 RGB, rows top-down: the last frame drawn */
} duel_render;

/* An off-screen OpenGL context for size x size images. 0, or -1 with one
 * line in err (bad size, out of memory, no OSMesa context). */
int duel_render_open(duel_render *r, int size, char *err, size_t err_len);
void duel_render_close(duel_render *r);

/* Draws frame f into r->rgb: duel_render_frame_info without a legend,
 * food line or trails. */
void duel_render_frame(duel_render *r, const duel_frame *f, unsigned flags);
/* The same with what info names (NULL: nothing more). */
void duel_render_frame_info(duel_render *r, const duel_frame *f, unsigned flags, const duel_render_info *info);

/* The width in pixels of s in the frames' text at dot pixels a dot. */
double duel_render_text_width(const char *s, double dot);

/* Board position (board units) -> image pixel coordinates, as above. */
void duel_render_to_pixel(int size, double x, double y, double *px, double *py);

/* Writes r->rgb to path as an 8-bit RGB PNG (no time stamp: the same frame
 * gives the same bytes), through a temporary file beside it renamed over
 * path once complete. 0, or -1 with one line in err naming the file (nothing
 * is left under path or the temporary name). */
int duel_render_write_png(const duel_render *r, const char *path, char *err, size_t err_len);

#endif /* DUEL_RENDER_H */
