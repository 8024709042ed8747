/* duel_render.h - one duel frame drawn with OpenGL into an OSMesa off-screen buffer (no display), and written as PNG. */
/* tools/render/: replays, frames, videos and network pictures: a game as frames, drawn with OSMesa and written with libpng, ffmpeg and Graphviz run as programs (docs/render.md). */
#ifndef DUEL_RENDER_H
#define DUEL_RENDER_H

#include <stddef.h>
#include <stdint.h>

#include "duel_replay.h"

/*
 * The picture (docs/render.md): a square image of size x size pixels; a
 * strip of hud = 3 * size / 40 pixels at the top (energy bars, step number),
 * a margin of m = size / 40 below the board, and the 600 x 600 board as a
 * square of side b = size - hud - m at ox = (size - b) / 2 from the left
 * (integer divisions; size 600: hud 45, b 540, ox 30, 0.9 pixel per unit).
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
#define DUEL_RGB_DIGITS 0xe8e8e8u   /* the step number (the winner's colour on a won game's last frame) */

#define DUEL_FOOD_DRAW_RADIUS 5 /* board units */

/* flags */
#define DUEL_RENDER_SENSORS 1u /* the rangefinder sector boundaries */

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

/* Draws frame f into r->rgb. */
void duel_render_frame(duel_render *r, const duel_frame *f, unsigned flags);

/* Board position (board units) -> image pixel coordinates, as above. */
void duel_render_to_pixel(int size, double x, double y, double *px, double *py);

/* Writes r->rgb to path as an 8-bit RGB PNG (no time stamp: the same frame
 * gives the same bytes), through a temporary file beside it renamed over
 * path once complete. 0, or -1 with one line in err naming the file (nothing
 * is left under path or the temporary name). */
int duel_render_write_png(const duel_render *r, const char *path, char *err, size_t err_len);

#endif /* DUEL_RENDER_H */
