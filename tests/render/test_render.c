/* test_render.c - replays and rendering: frames recorded from a game, frames drawn off-screen, written as PNG and read back pixel by pixel. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>
#include <png.h>

#include "duel_render.h"
#include "duel_replay.h"

#define TR_SIZE 600
#define TR_PI 3.14159265358979323846

/* A scratch directory per test run. */
static char tr_dir[64];

static int tr_setup(void **state)
{
    (void)state;
    snprintf(tr_dir, sizeof tr_dir, "/tmp/test_render.XXXXXX");
    return mkdtemp(tr_dir) == NULL ? -1 : 0;
}

static int tr_teardown(void **state)
{
    DIR *d = opendir(tr_dir);
    struct dirent *e;
    char path[sizeof tr_dir + 260];
    (void)state;
    if (d == NULL)
        return -1;
    while ((e = readdir(d)) != NULL)
        if (e->d_name[0] != '.' || (e->d_name[1] != '\0' && strcmp(e->d_name, "..") != 0)) {
            snprintf(path, sizeof path, "%s/%s", tr_dir, e->d_name);
            remove(path);
        }
    closedir(d);
    return rmdir(tr_dir);
}

/* The number of entries in the scratch directory whose name contains s. */
static int tr_count_files(const char *s)
{
    DIR *d = opendir(tr_dir);
    struct dirent *e;
    int n = 0;
    assert_non_null(d);
    while ((e = readdir(d)) != NULL)
        n += strstr(e->d_name, s) != NULL;
    closedir(d);
    return n;
}

/* ---- the picture's geometry, as docs/render.md states it ------------------ */

/* Board position -> the pixel that holds it (integer divisions as documented). */
static void tr_pixel(int size, double x, double y, int *i, int *j)
{
    int hud = size * 3 / 40, m = size / 30, b = size - hud - m, ox = (size - b) / 2;
    double px = ox + x * b / 600.0, py = hud + (600.0 - y) * b / 600.0, qx, qy;
    duel_render_to_pixel(size, x, y, &qx, &qy);
    assert_true(fabs(px - qx) < 1e-9 && fabs(py - qy) < 1e-9);
    *i = (int)floor(px);
    *j = (int)floor(py);
}

/* A decoded PNG: RGB rows top-down. */
typedef struct tr_image {
    int w, h;
    uint8_t *rgb;
} tr_image;

static void tr_read_png(const char *path, tr_image *img)
{
    png_image pi;
    memset(&pi, 0, sizeof pi);
    pi.version = PNG_IMAGE_VERSION;
    assert_true(png_image_begin_read_from_file(&pi, path));
    pi.format = PNG_FORMAT_RGB;
    img->w = (int)pi.width;
    img->h = (int)pi.height;
    img->rgb = (uint8_t *)malloc(PNG_IMAGE_SIZE(pi));
    assert_non_null(img->rgb);
    assert_true(png_image_finish_read(&pi, NULL, img->rgb, 0, NULL));
}

static uint32_t tr_at(const tr_image *img, int i, int j)
{
    const uint8_t *p;
    assert_true(i >= 0 && i < img->w && j >= 0 && j < img->h);
    p = img->rgb + ((size_t)j * (size_t)img->w + (size_t)i) * 3;
    return (uint32_t)p[0] << 16 | (uint32_t)p[1] << 8 | p[2];
}

static uint32_t tr_at_board(const tr_image *img, double x, double y)
{
    int i, j;
    tr_pixel(img->w, x, y, &i, &j);
    return tr_at(img, i, j);
}

/* Pixels of colour c in [x0, x1) x [y0, y1), clipped to the image. */
static long tr_count(const tr_image *img, int x0, int y0, int x1, int y1, uint32_t c)
{
    long n = 0;
    int i, j;
    for (j = y0 < 0 ? 0 : y0; j < y1 && j < img->h; j++)
        for (i = x0 < 0 ? 0 : x0; i < x1 && i < img->w; i++)
            n += tr_at(img, i, j) == c;
    return n;
}

/* Draws f, writes it as name in the scratch directory, reads it back. */
static void tr_render(duel_render *r, const duel_frame *f, unsigned flags, const char *name, tr_image *img)
{
    char path[256], err[256];
    snprintf(path, sizeof path, "%s/%s", tr_dir, name);
    duel_render_frame(r, f, flags);
    assert_int_equal(duel_render_write_png(r, path, err, sizeof err), 0);
    tr_read_png(path, img);
    assert_int_equal(img->w, r->size);
    assert_int_equal(img->h, r->size);
    /* what was written is exactly what was drawn */
    assert_memory_equal(img->rgb, r->rgb, (size_t)r->size * (size_t)r->size * 3);
}

static duel_angle tr_degrees(double deg)
{
    return (duel_angle)(uint32_t)llround(fmod(deg + 360.0, 360.0) / 360.0 * 4294967296.0);
}

/* A known state: training food, west at (150, 450) heading east, east at
 * (420, 180) heading north, step 8. */
static void tr_known(duel_frame *f)
{
    memset(f, 0, sizeof *f);
    assert_int_equal(duel_world_init(&f->w, DUEL_TRAINING), DUEL_OK);
    f->w.robot[DUEL_WEST].x = DUEL_FIX(150);
    f->w.robot[DUEL_WEST].y = DUEL_FIX(450);
    f->w.robot[DUEL_WEST].heading = tr_degrees(0);
    f->w.robot[DUEL_EAST].x = DUEL_FIX(420);
    f->w.robot[DUEL_EAST].y = DUEL_FIX(180);
    f->w.robot[DUEL_EAST].heading = tr_degrees(90);
    f->t = f->w.t = 8;
}

static void test_known_state(void **state)
{
    duel_render r;
    duel_frame f;
    tr_image img;
    char err[256];
    int s, i, j, by;
    long n_west, n_step;
    duel_render_geom g;
    (void)state;

    assert_int_equal(duel_render_open(&r, TR_SIZE, err, sizeof err), 0);
    tr_known(&f);
    tr_render(&r, &f, 0, "known.png", &img);

    /* the board's background where nothing is, and around the board */
    assert_int_equal(tr_at_board(&img, 520, 520), DUEL_RGB_BOARD);
    assert_int_equal(tr_at_board(&img, 80, 60), DUEL_RGB_BOARD);
    assert_int_equal(tr_at(&img, 2, TR_SIZE - 2), DUEL_RGB_FRAME);
    assert_int_equal(tr_at(&img, TR_SIZE - 3, TR_SIZE / 2), DUEL_RGB_FRAME);
    /* every food item at its position, one item eaten leaves the board behind */
    for (i = 0; i < DUEL_TRAIN_FOOD; i++)
        assert_int_equal(tr_at_board(&img, f.w.food_x[i] / 65536.0, f.w.food_y[i] / 65536.0), DUEL_RGB_FOOD);
    /* each robot's colour at its centre, the white heading mark ahead of it
     * (not behind), the outline at its rim */
    assert_int_equal(tr_at_board(&img, 150, 450), DUEL_RGB_WEST);
    assert_int_equal(tr_at_board(&img, 150 + 6, 450), DUEL_RGB_NOSE);
    assert_int_equal(tr_at_board(&img, 150 - 6, 450), DUEL_RGB_WEST);
    assert_int_equal(tr_at_board(&img, 150, 450 + 6), DUEL_RGB_WEST);
    assert_int_equal(tr_at_board(&img, 420, 180), DUEL_RGB_EAST);
    assert_int_equal(tr_at_board(&img, 420, 180 + 6), DUEL_RGB_NOSE);
    assert_int_equal(tr_at_board(&img, 420, 180 - 6), DUEL_RGB_EAST);
    assert_int_equal(tr_at_board(&img, 420 + 6, 180), DUEL_RGB_EAST);
    /* the outline is under a pixel wide at 0.89 pixel a unit: the rim pixel
     * is mostly outline (green well below the robot's 0x77 and the board's) */
    assert_true(((tr_at_board(&img, 150 - 9.6, 450) >> 8) & 255) < 0x60);
    assert_int_equal(tr_at_board(&img, 150 - 12, 450), DUEL_RGB_BOARD);
    /* the energy bars (1200 of 1200 + 9 * 200): west filled from the left to
     * 40 %, east from the right */
    duel_render_geom_of(TR_SIZE, &g);
    by = (int)((g.bar_y0 + g.bar_y1) / 2);
    {
        double len = g.bar_x1[0] - g.bar_x0[0];
        assert_int_equal(tr_at(&img, (int)(g.bar_x0[0] + len / 5), by), DUEL_RGB_WEST);
        assert_int_equal(tr_at(&img, (int)(g.bar_x0[0] + len * 7 / 10), by), DUEL_RGB_BAR_EMPTY);
        assert_int_equal(tr_at(&img, (int)(g.bar_x1[1] - len / 5), by), DUEL_RGB_EAST);
        assert_int_equal(tr_at(&img, (int)(g.bar_x1[1] - len * 7 / 10), by), DUEL_RGB_BAR_EMPTY);
    }
    /* the energy numbers beside the bars and "step 8" in the middle, in the
     * text colour; no legend row without names */
    n_west = tr_count(&img, (int)g.num_x0[0], (int)g.bar_y0, (int)g.num_x1[0], (int)g.bar_y1 + 3, DUEL_RGB_TEXT);
    assert_true(n_west > 20);
    assert_true(tr_count(&img, (int)g.num_x0[1], (int)g.bar_y0, (int)g.num_x1[1], (int)g.bar_y1 + 3, DUEL_RGB_TEXT) > 20);
    n_step = tr_count(&img, TR_SIZE / 2 - 40, (int)g.bar_y0, TR_SIZE / 2 + 40, (int)g.bar_y1 + 3, DUEL_RGB_TEXT);
    assert_true(n_step > 30);
    assert_int_equal(tr_count(&img, 0, 0, TR_SIZE, (int)g.bar_y0 - 1, DUEL_RGB_TEXT), 0);
    free(img.rgb);

    f.t = 0;
    f.w.food_mask &= ~(1u << 4); /* the middle item, at (300, 300) */
    f.w.robot[DUEL_WEST].energy = DUEL_FIX(2400);
    tr_render(&r, &f, 0, "eaten.png", &img);
    assert_int_equal(tr_at_board(&img, 300, 300), DUEL_RGB_BOARD);
    assert_int_equal(tr_at_board(&img, 200, 300), DUEL_RGB_FOOD);
    /* "step 0" and 2400 are other pixels than "step 8" and 1200 */
    assert_true(tr_count(&img, TR_SIZE / 2 - 40, (int)g.bar_y0, TR_SIZE / 2 + 40, (int)g.bar_y1 + 3, DUEL_RGB_TEXT) !=
                n_step);
    assert_true(tr_count(&img, (int)g.num_x0[0], (int)g.bar_y0, (int)g.num_x1[0], (int)g.bar_y1 + 3, DUEL_RGB_TEXT) !=
                n_west);
    {
        double len = g.bar_x1[0] - g.bar_x0[0];
        assert_int_equal(tr_at(&img, (int)(g.bar_x0[0] + len * 7 / 10), by), DUEL_RGB_WEST); /* 80 % now */
    }
    free(img.rgb);

    /* the sensor boundaries: heading + 36 degrees from the west robot, 100
     * units out, only with the flag; nothing else moves */
    tr_render(&r, &f, DUEL_RENDER_SENSORS, "sensors.png", &img);
    s = 0;
    for (j = -1; j <= 1; j++)
        for (i = -1; i <= 1; i++) {
            int pi, pj;
            tr_pixel(TR_SIZE, 150 + 100 * cos(TR_PI / 5), 450 + 100 * sin(TR_PI / 5), &pi, &pj);
            s += tr_at(&img, pi + i, pj + j) != DUEL_RGB_BOARD;
        }
    assert_true(s >= 2);
    assert_int_equal(tr_at_board(&img, 150, 450), DUEL_RGB_WEST);
    assert_int_equal(tr_at_board(&img, 420, 180), DUEL_RGB_EAST);
    assert_int_equal(tr_at_board(&img, 520, 520), DUEL_RGB_BOARD);
    free(img.rgb);
    duel_render_close(&r);
}

/* A game that ends in a collision: the replay's frames, and its last frame
 * drawn with both robots where the replay has them, within 20 units. */
static void test_collision_frame(void **state)
{
    duel_controller west = {NULL, DUEL_FORAGER_HUNTER}, east = {NULL, DUEL_IDLE};
    duel_replay rep;
    duel_result res;
    duel_render r;
    tr_image img;
    const duel_frame *last;
    char err[256];
    double dx, dy, d, cx[2], cy[2];
    long n[2];
    int s, i, j;
    (void)state;

    assert_int_equal(duel_play(&west, &east, DUEL_TRAINING, &res, NULL, NULL), DUEL_OK);
    assert_int_equal(res.outcome, DUEL_WEST_WINS);
    duel_replay_init(&rep);
    assert_int_equal(duel_replay_from_game(&rep, &west, &east, DUEL_TRAINING), 0);
    /* T frames plus the final state, t = index, the game's outcome at the end */
    assert_int_equal(rep.n, res.steps + 1);
    for (i = 0; i < (int)rep.n; i++)
        assert_int_equal(rep.frames[i].t, (uint32_t)i);
    assert_int_equal(rep.frames[0].w.robot[DUEL_WEST].x, DUEL_FIX(100));
    last = &rep.frames[rep.n - 1];
    assert_int_equal(last->ev.outcome, DUEL_WEST_WINS);
    assert_int_equal(rep.frames[rep.n - 2].ev.outcome, DUEL_WEST_WINS);
    assert_int_equal(rep.frames[rep.n - 3].ev.outcome, DUEL_RUNNING);
    assert_int_equal(last->w.robot[DUEL_WEST].energy, res.energy[DUEL_WEST]);
    assert_int_equal(last->w.robot[DUEL_EAST].energy, res.energy[DUEL_EAST]);
    for (i = 0; i < DUEL_N_OUTPUTS; i++)
        assert_int_equal(last->out[0][i] | last->out[1][i], 0);
    dx = (last->w.robot[0].x - last->w.robot[1].x) / 65536.0;
    dy = (last->w.robot[0].y - last->w.robot[1].y) / 65536.0;
    d = sqrt(dx * dx + dy * dy);
    assert_true(d < DUEL_COLLIDE_DIST);

    assert_int_equal(duel_render_open(&r, TR_SIZE, err, sizeof err), 0);
    tr_render(&r, last, 0, "collision.png", &img);
    /* each robot's colour at the pixel of its centre in the replay */
    for (s = 0; s < 2; s++)
        assert_int_equal(tr_at_board(&img, last->w.robot[s].x / 65536.0, last->w.robot[s].y / 65536.0),
                         s == DUEL_WEST ? DUEL_RGB_WEST : DUEL_RGB_EAST);
    /* the centroid of each robot's pixels, back in board units, is where the
     * replay has the robot, so the picture shows them within 20 units */
    for (s = 0; s < 2; s++) {
        cx[s] = cy[s] = 0;
        n[s] = 0;
    }
    for (j = 0; j < img.h; j++)
        for (i = 0; i < img.w; i++) {
            uint32_t c = tr_at(&img, i, j);
            s = c == DUEL_RGB_WEST ? 0 : (c == DUEL_RGB_EAST ? 1 : -1);
            if (s < 0 || j < TR_SIZE * 3 / 40 || j >= TR_SIZE - TR_SIZE / 30) /* the strips */
                continue;
            cx[s] += i + 0.5;
            cy[s] += j + 0.5;
            n[s]++;
        }
    for (s = 0; s < 2; s++) {
        double px, py, k = (TR_SIZE - TR_SIZE * 3 / 40 - TR_SIZE / 30) / 600.0;
        assert_true(n[s] > 100);
        duel_render_to_pixel(TR_SIZE, last->w.robot[s].x / 65536.0, last->w.robot[s].y / 65536.0, &px, &py);
        dx = (cx[s] / n[s] - px) / k;
        dy = (cy[s] / n[s] - py) / k;
        assert_true(sqrt(dx * dx + dy * dy) < 2.0);
    }
    /* the outcome on the last frame, in the bottom strip: its text and a disc
     * in the winner's colour, none in the loser's */
    j = TR_SIZE - TR_SIZE / 30;
    assert_true(tr_count(&img, 0, j, TR_SIZE, TR_SIZE, DUEL_RGB_TEXT) > 200);
    assert_true(tr_count(&img, 0, j, TR_SIZE, TR_SIZE, DUEL_RGB_WEST) > 20);
    assert_int_equal(tr_count(&img, 0, j, TR_SIZE, TR_SIZE, DUEL_RGB_EAST), 0);
    free(img.rgb);

    /* with the legend, the food line and the trails (what render draws):
     * text in both halves of the legend row, the dim food line on a frame
     * before the last, west's trail where it started (it moved away; idle
     * did not) and half way, and none of that without the info */
    {
        duel_render_info info;
        duel_render_geom g;
        const duel_frame *mid = &rep.frames[rep.n / 2];
        int ly;
        duel_render_geom_of(TR_SIZE, &g);
        ly = (int)g.legend_y;
        info.west = "builtin:forager-hunter";
        info.east = "builtin:idle";
        info.food_config = DUEL_TRAINING;
        info.trail = rep.frames;
        info.n_trail = rep.n / 2 + 1;
        duel_render_frame_info(&r, mid, DUEL_RENDER_TRAILS, &info);
        assert_int_equal(duel_render_write_png(&r, "trails.png", err, sizeof err), 0);
        tr_read_png("trails.png", &img);
        assert_true(tr_count(&img, 0, ly - 6, TR_SIZE / 2, ly + 6, DUEL_RGB_TEXT) > 100);
        assert_true(tr_count(&img, TR_SIZE / 2, ly - 6, TR_SIZE, ly + 6, DUEL_RGB_TEXT) > 50);
        assert_true(tr_count(&img, 0, ly - 6, TR_SIZE / 2, ly + 6, DUEL_RGB_WEST) > 10); /* the colour disc */
        assert_true(tr_count(&img, TR_SIZE / 2, ly - 6, TR_SIZE, ly + 6, DUEL_RGB_EAST) > 10);
        assert_true(tr_count(&img, 0, TR_SIZE - TR_SIZE / 30, TR_SIZE, TR_SIZE, DUEL_RGB_TEXT_DIM) > 50);
        assert_int_equal(tr_at_board(&img, rep.frames[0].w.robot[0].x / 65536.0, rep.frames[0].w.robot[0].y / 65536.0),
                         DUEL_RGB_TRAIL_WEST);
        assert_int_equal(tr_at_board(&img, rep.frames[rep.n / 4].w.robot[0].x / 65536.0,
                                     rep.frames[rep.n / 4].w.robot[0].y / 65536.0),
                         DUEL_RGB_TRAIL_WEST);
        assert_int_equal(tr_count(&img, 0, 0, TR_SIZE, TR_SIZE, DUEL_RGB_TRAIL_EAST), 0);
        free(img.rgb);
        remove("trails.png");
        /* names far too long for the row: each loses its start and they stay
         * apart (a gap of the frame's colour in the middle of the row) */
        {
            static char lw[400], le[400];
            memset(lw, 'w', sizeof lw - 1);
            memset(le, 'e', sizeof le - 1);
            lw[100] = le[50] = '/';
            info.west = lw;
            info.east = le;
            duel_render_frame_info(&r, mid, 0, &info);
            assert_int_equal(duel_render_write_png(&r, "trails.png", err, sizeof err), 0);
            tr_read_png("trails.png", &img);
            assert_true(tr_count(&img, 0, ly - 6, TR_SIZE / 2 - 10, ly + 6, DUEL_RGB_TEXT) > 300);
            assert_true(tr_count(&img, TR_SIZE / 2 + 10, ly - 6, TR_SIZE, ly + 6, DUEL_RGB_TEXT) > 300);
            assert_int_equal(tr_count(&img, TR_SIZE / 2 - 4, ly - 6, TR_SIZE / 2 + 4, ly + 6, DUEL_RGB_TEXT), 0);
            free(img.rgb);
            remove("trails.png");
        }
        duel_render_frame(&r, mid, DUEL_RENDER_TRAILS);
        assert_int_equal(duel_render_write_png(&r, "trails.png", err, sizeof err), 0);
        tr_read_png("trails.png", &img);
        assert_int_equal(tr_count(&img, 0, 0, TR_SIZE, TR_SIZE, DUEL_RGB_TRAIL_WEST), 0);
        assert_int_equal(tr_count(&img, 0, ly - 6, TR_SIZE, ly + 6, DUEL_RGB_TEXT), 0);
        assert_int_equal(tr_count(&img, 0, TR_SIZE - TR_SIZE / 30, TR_SIZE, TR_SIZE, DUEL_RGB_TEXT_DIM), 0);
        free(img.rgb);
        remove("trails.png");
    }
    duel_render_close(&r);
    duel_replay_free(&rep);
    assert_null(rep.frames);
}

/* The same frame gives the same bytes; no temporary file stays behind. */
static void test_deterministic(void **state)
{
    duel_render r;
    duel_frame f;
    tr_image a, b;
    char err[256], pa[256], pb[256];
    FILE *fa, *fb;
    int ca, cb;
    (void)state;

    tr_known(&f);
    assert_int_equal(duel_render_open(&r, 256, err, sizeof err), 0);
    tr_render(&r, &f, DUEL_RENDER_SENSORS, "a.png", &a);
    duel_render_close(&r);
    assert_int_equal(duel_render_open(&r, 256, err, sizeof err), 0);
    tr_render(&r, &f, DUEL_RENDER_SENSORS, "b.png", &b);
    duel_render_close(&r);
    snprintf(pa, sizeof pa, "%s/a.png", tr_dir);
    snprintf(pb, sizeof pb, "%s/b.png", tr_dir);
    fa = fopen(pa, "rb");
    fb = fopen(pb, "rb");
    assert_non_null(fa);
    assert_non_null(fb);
    do {
        ca = fgetc(fa);
        cb = fgetc(fb);
        assert_int_equal(ca, cb);
    } while (ca != EOF);
    fclose(fa);
    fclose(fb);
    assert_int_equal(tr_count_files(".tmp"), 0);
    free(a.rgb);
    free(b.rgb);
}

/* A PNG that cannot be written: -1, one line naming the file, nothing left;
 * an existing file is replaced whole. Sizes out of range are refused. */
static void test_write_errors(void **state)
{
    duel_render r;
    duel_frame f;
    tr_image img;
    char err[256], path[256];
    FILE *old;
    (void)state;

    assert_int_equal(duel_render_open(&r, 10, err, sizeof err), -1);
    assert_non_null(strstr(err, "size 10"));
    assert_int_equal(duel_render_open(&r, DUEL_RENDER_MAX_SIZE + 1, err, sizeof err), -1);

    tr_known(&f);
    assert_int_equal(duel_render_open(&r, 128, err, sizeof err), 0);
    duel_render_frame(&r, &f, 0);
    snprintf(path, sizeof path, "%s/missing/frame.png", tr_dir);
    assert_int_equal(duel_render_write_png(&r, path, err, sizeof err), -1);
    assert_non_null(strstr(err, path));
    assert_null(strchr(err, '\n'));

    snprintf(path, sizeof path, "%s/old.png", tr_dir);
    old = fopen(path, "w");
    assert_non_null(old);
    fputs("not a png\n", old);
    fclose(old);
    assert_int_equal(duel_render_write_png(&r, path, err, sizeof err), 0);
    tr_read_png(path, &img);
    assert_int_equal(img.w, 128);
    assert_int_equal(tr_count_files(".tmp"), 0);
    free(img.rgb);
    duel_render_close(&r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_known_state),
        cmocka_unit_test(test_collision_frame),
        cmocka_unit_test(test_deterministic),
        cmocka_unit_test(test_write_errors),
    };
    return cmocka_run_group_tests(tests, tr_setup, tr_teardown);
}
