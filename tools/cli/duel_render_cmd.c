/* duel_render_cmd.c - `duel_evolve render` (a game's frames as PNG files, and a video through ffmpeg) and `duel_evolve render-net` (a champion's network as PNG through Graphviz dot). */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include <sys/stat.h>
#include <zlib.h>

#include "duel_cli.h"
#include "duel_ctrl.h"
#include "duel_exec.h"
#include "duel_files.h"
#include "duel_outputs.h"
#include "duel_text.h"
#include "duel_render.h"
#include "duel_html.h"
#include "duel_replay.h"
#include "duel_trace.h"
#include "duel_world_cfg.h"

#define DUEL_RC_PATH 4096

static const char duel_render_usage_line[] =
    "usage: duel_evolve render (LOG.lcm | A B [--food K|training] [--side west|east] [--world NAME|FILE]) --out DIR "
    "[--size 600] "
    "[--every N] [--sensors] [--trails] [--video FILE.mp4] [--fps 30] [--html FILE.html] [--force]\n";

/* "--opt N" with lo <= N <= hi. 0, or -1 after one line on stderr. */
static int duel_rc_int(const char *cmd, const char *opt, const char *v, long lo, long hi, int *out)
{
    char *end;
    long k;
    errno = 0;
    k = strtol(v, &end, 10);
    if (*v == '\0' || *end != '\0' || errno || k < lo || k > hi) {
        fprintf(stderr, "duel_evolve: %s: %s takes an integer from %ld to %ld, not '%s'\n", cmd, opt, lo, hi, duel_esc(v));
        return -1;
    }
    *out = (int)k;
    return 0;
}

/* A file name an external program cannot take for an option. */
static const char *duel_rc_arg(const char *path, char *buf, size_t len)
{
    if (path[0] != '-')
        return path;
    snprintf(buf, len, "./%s", path);
    return buf;
}

/* Creates and removes a file named path + suffix: the place can be written
 * (as root too, where access() says yes to everything). 0 or -1 (errno). */
static int duel_rc_probe(const char *path, const char *suffix)
{
    char tmp[DUEL_RC_PATH];
    int fd;
    if (snprintf(tmp, sizeof tmp, "%s%s", path, suffix) >= (int)sizeof tmp) {
        errno = ENAMETOOLONG;
        return -1;
    }
    fd = open(tmp, O_WRONLY | O_CREAT | O_TRUNC, 0666); /* a stale one of ours is taken over */
    if (fd < 0)
        return -1;
    close(fd);
    return unlink(tmp);
}

/* Where an output that another program makes as PATH.tmp and that is then
 * renamed goes (duel_out_target): a link is followed to the file it names,
 * and a place that is no regular file (a pipe, a device) is refused, since
 * nothing can be renamed over it. 0, or -1 after one line on stderr. */
static int duel_rc_target(const char *cmd, const char *path, char target[DUEL_RC_PATH], const char *what)
{
    int direct = 0;
    if (duel_out_target(path, target, DUEL_RC_PATH, &direct) == 0 && !direct)
        return 0;
    if (direct)
        fprintf(stderr, "duel_evolve: %s: %s: cannot write: not a regular file (the %s is written to a temporary "
                        "file and renamed)\n", cmd, duel_esc(path), what);
    else
        fprintf(stderr, "duel_evolve: %s: %s: cannot write: %s\n", cmd, duel_esc(path), strerror(errno));
    return -1;
}

/* What marks the outputs as this command's (a PNG text chunk, an MP4 comment), so that a later render
 * replaces its own files and refuses anybody else's (duel_outputs.h). */
#define DUEL_RC_FRAME_MARK "duel_evolve render"
#define DUEL_RC_NET_MARK "duel_evolve render-net"
#define DUEL_RC_VIDEO_MARK "duel_evolve render"

/* 1 when mark occurs in the len bytes at p. */
static int duel_rc_has(const uint8_t *p, size_t len, const char *mark)
{
    size_t i, n = strlen(mark);
    for (i = 0; i + n <= len; i++)
        if (p[i] == (uint8_t)mark[0] && memcmp(p + i, mark, n) == 0)
            return 1;
    return 0;
}

static int duel_rc_is_frame(const uint8_t *head, size_t len, const char *path)
{
    (void)path;
    return len > 8 && memcmp(head, "\x89PNG", 4) == 0 && duel_rc_has(head, len, DUEL_RC_FRAME_MARK);
}

static int duel_rc_is_net(const uint8_t *head, size_t len, const char *path)
{
    (void)path;
    return len > 8 && memcmp(head, "\x89PNG", 4) == 0 && duel_rc_has(head, len, DUEL_RC_NET_MARK);
}

/* An MP4 with the comment: its first 256 KiB (faststart puts the metadata there), else its last. */
static int duel_rc_is_video(const uint8_t *head, size_t len, const char *path)
{
    static uint8_t buf[256 * 1024];
    FILE *f;
    size_t got;
    int yes = 0;
    (void)head;
    (void)len;
    f = duel_fopen_regular(path);
    if (f == NULL)
        return 0;
    got = fread(buf, 1, sizeof buf, f);
    yes = duel_rc_has(buf, got, DUEL_RC_VIDEO_MARK);
    if (!yes && got == sizeof buf && fseek(f, -(long)sizeof buf, SEEK_END) == 0) {
        got = fread(buf, 1, sizeof buf, f);
        yes = duel_rc_has(buf, got, DUEL_RC_VIDEO_MARK);
    }
    fclose(f);
    return yes;
}

static const duel_out_kind duel_rc_frame_kind = {"a frame from duel_evolve render", NULL, duel_rc_is_frame};

/* The number of a frame file's name (frame-NNNNN.png), or -1 for any other name. */
static long duel_rc_frame_no(const char *name)
{
    size_t i;
    if (strlen(name) != 15 || strncmp(name, "frame-", 6) != 0 || strcmp(name + 11, ".png") != 0)
        return -1;
    for (i = 6; i < 11; i++)
        if (name[i] < '0' || name[i] > '9')
            return -1;
    return strtol(name + 6, NULL, 10);
}

/* Whether the directory dir (when it exists) may take a render's frames: a directory holding nothing but
 * frame-NNNNN.png files (and temporaries of ours). 0, or 2 after one line naming the first other entry. */
static int duel_rc_frames_dir(const char *cmd, const char *dir)
{
    struct stat st;
    DIR *d;
    struct dirent *e;
    int rc = 0;
    if (stat(dir, &st) != 0)
        return 0; /* created */
    if (!S_ISDIR(st.st_mode)) {
        fprintf(stderr, "duel_evolve: %s: --out %s is not a directory\n", cmd, duel_esc(dir));
        return 2;
    }
    if ((d = opendir(dir)) == NULL) {
        fprintf(stderr, "duel_evolve: %s: --out %s: cannot list it: %s\n", cmd, duel_esc(dir), strerror(errno));
        return 2;
    }
    while (rc == 0 && (e = readdir(d)) != NULL) {
        const char *n = e->d_name;
        size_t len = strlen(n);
        char esc[1100];
        if (strcmp(n, ".") == 0 || strcmp(n, "..") == 0 || duel_rc_frame_no(n) >= 0 ||
            (len > 4 && strcmp(n + len - 4, ".tmp") == 0 && (strncmp(n, "frame-", 6) == 0 || strncmp(n, ".probe.", 7) == 0)))
            continue;
        fprintf(stderr, "duel_evolve: %s: --out %s holds '%s', which is not a frame of duel_evolve render: choose "
                        "another --out (an empty or new directory)\n", cmd, duel_esc(dir), duel_text_escape(n, esc, sizeof esc));
        rc = 2;
    }
    closedir(d);
    return rc;
}

/* Removes the frames an earlier render left in dir beyond the n this one wrote, so the directory holds one game.
 * 0, or -1 after one line. */
static int duel_rc_drop_frames(const char *dir, unsigned n)
{
    char path[DUEL_RC_PATH];
    DIR *d = opendir(dir);
    struct dirent *e;
    int rc = 0;
    if (d == NULL)
        return 0;
    while ((e = readdir(d)) != NULL) {
        long no = duel_rc_frame_no(e->d_name);
        if (no < (long)n)
            continue;
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        if (unlink(path) != 0 && errno != ENOENT) {
            fprintf(stderr, "duel_evolve: render: %s: cannot remove an earlier render's frame: %s\n", duel_esc(path),
                    strerror(errno));
            rc = -1;
        }
    }
    closedir(d);
    return rc;
}
static const duel_out_kind duel_rc_net_kind = {"a picture from duel_evolve render-net", NULL, duel_rc_is_net};
static const duel_out_kind duel_rc_video_kind = {"a video from duel_evolve render", NULL, duel_rc_is_video};

static uint32_t duel_rc_be32(uint32_t v, uint8_t *p)
{
    p[0] = (uint8_t)(v >> 24);
    p[1] = (uint8_t)(v >> 16);
    p[2] = (uint8_t)(v >> 8);
    p[3] = (uint8_t)v;
    return v;
}

/* Graphviz's PNG at path with a tEXt chunk "Software: duel_evolve render-net" after its IHDR. 0 or -1 (errno). */
static int duel_rc_mark_png(const char *path)
{
    static const char key[] = "Software";
    uint8_t *png, *out, *c;
    size_t len, n = sizeof key + strlen(DUEL_RC_NET_MARK); /* key, NUL, text */
    int r;
    if (duel_file_read(path, (size_t)1 << 30, &png, &len) != 0)
        return -1;
    /* signature (8), then IHDR: length 13, type, 13 bytes, CRC: 33 bytes */
    if (len < 33 || memcmp(png, "\x89PNG\r\n\x1a\n", 8) != 0 || memcmp(png + 12, "IHDR", 4) != 0) {
        free(png);
        errno = EINVAL;
        return -1;
    }
    out = (uint8_t *)malloc(len + 12 + n);
    if (out == NULL) {
        free(png);
        errno = ENOMEM;
        return -1;
    }
    memcpy(out, png, 33);
    c = out + 33;
    duel_rc_be32((uint32_t)n, c);
    memcpy(c + 4, "tEXt", 4);
    memcpy(c + 8, key, sizeof key);
    memcpy(c + 8 + sizeof key, DUEL_RC_NET_MARK, strlen(DUEL_RC_NET_MARK));
    duel_rc_be32((uint32_t)crc32(0L, c + 4, (uInt)(4 + n)), c + 8 + n);
    memcpy(c + 12 + n, png + 33, len - 33);
    free(png);
    r = duel_file_replace(path, out, len + 12 + n);
    free(out);
    return r == 0 ? 0 : -1;
}

static double duel_rc_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* The game's frames from an LCM event log (`play --lcm-log`). 0, or -1
 * after one line on stderr. */
static int duel_rc_read_log(duel_replay *rep, const char *path)
{
    char err[512];
    if (duel_replay_from_lcm_log(rep, path, err, sizeof err) != 0) {
        fprintf(stderr, "duel_evolve: render: %s\n", duel_esc_msg(err));
        return -1;
    }
    return 0;
}

/* The game between the controllers specs a and b, a starting west or east. */
static int duel_rc_play(duel_replay *rep, const duel_rules *world, const char *a_spec, const char *b_spec, int food,
                        int a_west, char step_w[16], char step_e[16])
{
    duel_cli_ctrl a, b;
    int err;
    if (duel_cli_ctrl_open(&a, a_spec) != 0)
        return -1;
    if (duel_cli_ctrl_open(&b, b_spec) != 0) {
        duel_cli_ctrl_close(&a);
        return -1;
    }
    err = a_west ? duel_replay_from_game_rules(rep, world, &a.ctrl, &b.ctrl, food)
                 : duel_replay_from_game_rules(rep, world, &b.ctrl, &a.ctrl, food);
    snprintf(rep->west, sizeof rep->west, "%s", a_west ? a.name : b.name);
    snprintf(rep->east, sizeof rep->east, "%s", a_west ? b.name : a.name);
    snprintf(step_w, 16, "%s", duel_origin_step_text(a_west ? &a.origin : &b.origin));
    snprintf(step_e, 16, "%s", duel_origin_step_text(a_west ? &b.origin : &a.origin));
    duel_cli_ctrl_close(&a);
    duel_cli_ctrl_close(&b);
    if (err) {
        fprintf(stderr, "duel_evolve: render: the game failed (%d)\n", err);
        return -1;
    }
    return 0;
}

/* ffmpeg turns DIR/frame-00000.png ... (n frames) into an MP4 (H.264,
 * yuv420p, even dimensions) at fps, written to a temporary name and renamed
 * to video. 0, or -1 after one line on stderr. */
static int duel_rc_video(const char *ffmpeg, const char *dir, unsigned n, int fps, const char *video)
{
    char pattern[DUEL_RC_PATH], out[DUEL_RC_PATH], tmp[DUEL_RC_PATH], rate[16], frames[16], msg[512];
    char *argv[32];
    size_t i, j = 0;
    int argc = 0, st;

    /* "file:" first, as for the output: a directory named like a URL (http://...) is never fetched */
    memcpy(pattern, "file:", 5);
    j = 5;
    for (i = 0; dir[i] != '\0' && j + 2 < sizeof pattern; i++) { /* '%' is the pattern's escape */
        if (dir[i] == '%')
            pattern[j++] = '%';
        pattern[j++] = dir[i];
    }
    pattern[j] = '\0';
    if (snprintf(tmp, sizeof tmp, "%s.tmp", video) >= (int)sizeof tmp ||
        strlen(pattern) + 16 >= sizeof pattern || snprintf(out, sizeof out, "file:%s", tmp) >= (int)sizeof out) {
        fprintf(stderr, "duel_evolve: render: %s: name too long\n", duel_esc(video));
        return -1;
    }
    strcat(pattern, "/frame-%05d.png");
    snprintf(rate, sizeof rate, "%d", fps);
    snprintf(frames, sizeof frames, "%u", n);
    argv[argc++] = (char *)"ffmpeg";
    argv[argc++] = (char *)"-nostdin";
    argv[argc++] = (char *)"-hide_banner";
    argv[argc++] = (char *)"-loglevel";
    argv[argc++] = (char *)"error";
    argv[argc++] = (char *)"-framerate";
    argv[argc++] = rate;
    argv[argc++] = (char *)"-start_number";
    argv[argc++] = (char *)"0";
    argv[argc++] = (char *)"-i";
    argv[argc++] = pattern;
    argv[argc++] = (char *)"-frames:v";
    argv[argc++] = frames;
    argv[argc++] = (char *)"-vf";
    argv[argc++] = (char *)"pad=ceil(iw/2)*2:ceil(ih/2)*2";
    argv[argc++] = (char *)"-c:v";
    argv[argc++] = (char *)"libx264";
    argv[argc++] = (char *)"-pix_fmt";
    argv[argc++] = (char *)"yuv420p";
    argv[argc++] = (char *)"-metadata"; /* how a later --video recognises this file as ours (duel_rc_is_video) */
    argv[argc++] = (char *)"comment=" DUEL_RC_VIDEO_MARK;
    argv[argc++] = (char *)"-movflags";
    argv[argc++] = (char *)"+faststart"; /* the metadata at the start of the file */
    argv[argc++] = (char *)"-f";
    argv[argc++] = (char *)"mp4";
    argv[argc++] = (char *)"-y";
    argv[argc++] = out;
    argv[argc] = NULL;
    st = duel_exec_run(ffmpeg, argv, msg, sizeof msg);
    if (st != 0) {
        remove(tmp);
        if (st > 0)
            fprintf(stderr, "duel_evolve: render: %s: ffmpeg failed (exit status %d)%s%s\n", duel_esc(video), st,
                    msg[0] ? ": " : "", duel_esc_msg(msg));
        else
            fprintf(stderr, "duel_evolve: render: %s: %s\n", duel_esc(video), duel_esc_msg(msg));
        return -1;
    }
    if (duel_file_sync(tmp) != 0 || duel_file_commit(tmp, video) != 0) {
        fprintf(stderr, "duel_evolve: render: %s: cannot write: %s\n", duel_esc(video), strerror(errno));
        remove(tmp);
        return -1;
    }
    return 0;
}

/* The game's lines: food, sides and outcome; the world and the networks' step. */
static void duel_rc_say_game(const duel_replay *rep, int n_pos, const char *step_w, const char *step_e)
{
    const duel_frame *last = &rep->frames[rep->n - 1];
    char esc_w[1100], esc_e[1100];
    if (rep->food_config < 0)
        printf("training food, west %s, east %s: ", duel_text_escape(rep->west, esc_w, sizeof esc_w),
               duel_text_escape(rep->east, esc_e, sizeof esc_e));
    else
        printf("food configuration %d, west %s, east %s: ", rep->food_config,
               duel_text_escape(rep->west, esc_w, sizeof esc_w), duel_text_escape(rep->east, esc_e, sizeof esc_e));
    printf("%s after %u steps\n", duel_outcome_text(last->ev.outcome), (unsigned)last->t);
    /* what it was played in (issue 49): the world, and each side's network step when it was played here */
    printf("world %s (identity %016llx)", duel_rules_name(&rep->rules) != NULL ? duel_rules_name(&rep->rules) : "custom",
           (unsigned long long)duel_rules_id(&rep->rules));
    if (n_pos == 2)
        printf("; network step: west %s, east %s", step_w, step_e);
    else if (rep->step[0] != DUEL_TRACE_STEP_UNKNOWN || rep->step[1] != DUEL_TRACE_STEP_UNKNOWN)
        printf("; network step: west %s, east %s", duel_trace_step_name(rep->step[0]),
               duel_trace_step_name(rep->step[1])); /* as the log's net messages say */
    printf("\n");
}

int duel_cmd_render(int argc, char **argv)
{
    const char *pos[3] = {NULL, NULL, NULL}, *dir = NULL, *video = NULL, *world_arg = NULL, *html = NULL;
    duel_rules world = *duel_rules_v1();
    char step_w[16] = "", step_e[16] = "";
    int found = 0;
    char video_target[DUEL_RC_PATH];
    char ffmpeg[DUEL_RC_PATH], path[DUEL_RC_PATH], err[512], suffix[64];
    int i, n_pos = 0, size = 600, every = 1, fps = 30, food = DUEL_TRAINING, a_west = 1, game_opts = 0, rc = 0;
    int force = 0, dir_exists;
    unsigned flags = 0, n_out = 0;
    duel_replay rep;
    duel_render ren;
    duel_render_info info;
    size_t k;
    double t0, secs;
    long long html_bytes = 0;

    if (argc == 0) {
        fputs(duel_render_usage_line, stderr);
        return 2;
    }
    for (i = 0; i < argc; i++) {
        const char *opt = argv[i];
        if (opt[0] != '-') {
            if (n_pos == 2) {
                fprintf(stderr, "duel_evolve: render: unexpected argument '%s' (a log, or two controllers)\n", duel_esc(opt));
                return 2;
            }
            pos[n_pos++] = opt;
            continue;
        }
        if (strcmp(opt, "--sensors") == 0) {
            flags |= DUEL_RENDER_SENSORS;
            continue;
        }
        if (strcmp(opt, "--trails") == 0) {
            flags |= DUEL_RENDER_TRAILS;
            continue;
        }
        if (strcmp(opt, "--force") == 0) {
            force = 1;
            continue;
        }
        if (i + 1 >= argc) {
            static const char *const takes[] = {"--out", "--video", "--size", "--every", "--fps", "--food", "--side",
                                                "--world", "--html", NULL};
            return duel_cli_missing_value("render", opt, takes);
        }
        if (strcmp(opt, "--out") == 0) {
            dir = argv[++i];
        } else if (strcmp(opt, "--video") == 0) {
            video = argv[++i];
        } else if (strcmp(opt, "--html") == 0) {
            html = argv[++i];
        } else if (strcmp(opt, "--size") == 0) {
            if (duel_rc_int("render", opt, argv[++i], DUEL_RENDER_MIN_SIZE, DUEL_RENDER_MAX_SIZE, &size) != 0)
                return 2;
        } else if (strcmp(opt, "--every") == 0) {
            if (duel_rc_int("render", opt, argv[++i], 1, 1000, &every) != 0)
                return 2;
        } else if (strcmp(opt, "--fps") == 0) {
            if (duel_rc_int("render", opt, argv[++i], 1, 120, &fps) != 0)
                return 2;
        } else if (strcmp(opt, "--food") == 0) {
            game_opts = 1;
            if (strcmp(argv[++i], "training") == 0)
                food = DUEL_TRAINING;
            else if (duel_rc_int("render", opt, argv[i], 0, DUEL_CONFIGS - 1, &food) != 0)
                return 2;
        } else if (strcmp(opt, "--world") == 0) {
            world_arg = argv[++i];
            game_opts = 1;
        } else if (strcmp(opt, "--side") == 0) {
            const char *v = argv[++i];
            game_opts = 1;
            if (strcmp(v, "west") != 0 && strcmp(v, "east") != 0) {
                fprintf(stderr, "duel_evolve: render: --side takes west or east, not '%s'\n", duel_esc(v));
                return 2;
            }
            a_west = strcmp(v, "west") == 0;
        } else {
            fprintf(stderr, "duel_evolve: render: unknown option '%s' (see duel_evolve --help)\n", duel_esc(opt));
            return 2;
        }
    }
    if (n_pos == 0 || (dir == NULL && html == NULL)) {
        fputs(duel_render_usage_line, stderr);
        return 2;
    }
    if (dir == NULL && video != NULL) {
        fprintf(stderr, "duel_evolve: render: --video is made from the frames: it needs --out DIR\n");
        return 2;
    }
    if (n_pos == 1 && game_opts) {
        fprintf(stderr, "duel_evolve: render: --food, --side and --world choose a game to play, not one in a log\n");
        return 2;
    }
    /* a game to play is played in --world's world, else in that of the runs its champions come from, else v1 */
    if (n_pos == 2 && (world_arg != NULL ? duel_world_arg(&world, world_arg) != 0
                                         : duel_ctrl_world((const char *const *)pos, 2, &world, &found) != 0))
        return 2;
    /* everything that can be checked before the game is played and drawn */
    if (video != NULL) {
        if (duel_exec_find("ffmpeg", ffmpeg, sizeof ffmpeg) != 0) {
            fprintf(stderr, "duel_evolve: render: --video needs ffmpeg, which is not on PATH (Debian: apt-get install "
                            "ffmpeg)\n");
            return 2;
        }
        if (duel_out_allowed("render", "--video", video, &duel_rc_video_kind, force, pos, 2) != 0 ||
            duel_rc_target("render", video, video_target, "video") != 0)
            return 2;
        video = video_target;
        if (duel_rc_probe(video, ".tmp") != 0) {
            fprintf(stderr, "duel_evolve: render: %s: cannot write: %s\n", duel_esc(video), strerror(errno));
            return 2;
        }
    }
    if (html != NULL && duel_html_allowed("render", "--html", html, force, pos, 2, err, sizeof err) != 0) {
        fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(err));
        return 2;
    }
    /* the game, then the directory: bad input leaves nothing behind */
    duel_replay_init(&rep);
    if (n_pos == 1 ? duel_rc_read_log(&rep, pos[0]) : duel_rc_play(&rep, &world, pos[0], pos[1], food, a_west, step_w, step_e)) {
        duel_replay_free(&rep);
        return 2;
    }
    if (rep.n == 0) {
        fprintf(stderr, "duel_evolve: render: %s: no frame to draw\n", pos[0]);
        duel_replay_free(&rep);
        return 2;
    }
    if (html != NULL) {
        char title[600];
        struct stat st;
        snprintf(title, sizeof title, "%s vs %s", rep.west, rep.east);
        rc = duel_html_write_duel("render", html, &rep, title, force, pos, 2, err, sizeof err);
        if (rc != 0) {
            fprintf(stderr, "duel_evolve: render: %s\n", duel_esc_msg(err));
            duel_replay_free(&rep);
            return rc;
        }
        if (dir == NULL) {
            duel_rc_say_game(&rep, n_pos, step_w, step_e);
            printf("page: %s (%lld bytes, %u frames)\n", html, stat(html, &st) == 0 ? (long long)st.st_size : 0LL,
                   (unsigned)rep.n);
            duel_replay_free(&rep);
            if (fflush(stdout) != 0) {
                fprintf(stderr, "duel_evolve: render: cannot write the output: %s\n", strerror(errno));
                return 1;
            }
            return 0;
        }
        html_bytes = stat(html, &st) == 0 ? (long long)st.st_size : 0LL;
    }
    if (strlen(dir) + 32 > sizeof path) {
        fprintf(stderr, "duel_evolve: render: %s: name too long\n", duel_esc(dir));
        duel_replay_free(&rep);
        return 2;
    }
    /* every frame this will write: one already there that is not a frame of ours is not replaced */
    dir_exists = access(dir, F_OK) == 0;
    for (k = 0, n_out = 0;; k += (size_t)every) {
        if (k > rep.n - 1)
            k = rep.n - 1;
        snprintf(path, sizeof path, "%s/frame-%05u.png", dir, n_out++);
        if (dir_exists && duel_out_allowed("render", "--out", path, &duel_rc_frame_kind, force, pos, 2) != 0) {
            duel_replay_free(&rep);
            return 2;
        }
        if (k == rep.n - 1)
            break;
    }
    n_out = 0;
    if (duel_mkdir(dir) != 0) {
        fprintf(stderr, "duel_evolve: render: %s: cannot create the directory: %s\n", duel_esc(dir), strerror(errno));
        duel_replay_free(&rep);
        return 2;
    }
    snprintf(suffix, sizeof suffix, "/.probe.%ld.tmp", (long)getpid());
    if (duel_rc_probe(dir, suffix) != 0) {
        fprintf(stderr, "duel_evolve: render: %s: cannot write in the directory: %s\n", duel_esc(dir), strerror(errno));
        duel_replay_free(&rep);
        return 2;
    }
    /* an existing --out holds frames of an earlier render only: nothing else is mixed with this game's */
    if (duel_rc_frames_dir("render", dir) != 0) {
        duel_replay_free(&rep);
        return 2;
    }
    if (duel_render_open(&ren, size, err, sizeof err) != 0) {
        fprintf(stderr, "duel_evolve: render: %s\n", duel_esc_msg(err));
        duel_replay_free(&rep);
        return 1;
    }

    /* frames 0, N, 2N, ... and always the last one (the final state) */
    /* the legend names the controllers as the stdout line does */
    info.west = rep.west;
    info.east = rep.east;
    info.food_config = rep.food_config;
    info.trail = rep.frames;
    t0 = duel_rc_now();
    for (k = 0;; k += (size_t)every) {
        if (k > rep.n - 1)
            k = rep.n - 1;
        info.n_trail = k + 1;
        duel_render_frame_info(&ren, &rep.frames[k], flags, &info);
        snprintf(path, sizeof path, "%s/frame-%05u.png", dir, n_out);
        if (duel_render_write_png(&ren, path, err, sizeof err) != 0) {
            fprintf(stderr, "duel_evolve: render: %s\n", duel_esc_msg(err));
            rc = 1;
            break;
        }
        n_out++;
        if (k == rep.n - 1)
            break;
    }
    secs = duel_rc_now() - t0;
    duel_render_close(&ren);
    if (rc == 0 && duel_rc_drop_frames(dir, n_out) != 0)
        rc = 1;

    if (rc == 0) {
        duel_rc_say_game(&rep, n_pos, step_w, step_e);
        if (every == 1)
            printf("%u frames of %dx%d: %s/frame-00000.png .. frame-%05u.png (every step and the final state)\n",
                   n_out, size, size, dir, n_out - 1);
        else
            printf("%u frames of %dx%d: %s/frame-00000.png .. frame-%05u.png (every %d steps and the final state)\n",
                   n_out, size, size, dir, n_out - 1, every);
        printf("%u frames in %.2f s (%.1f frames/s, drawing and PNG writing)\n", n_out, secs,
               secs > 0 ? n_out / secs : 0.0);
        if (video != NULL) {
            if (duel_rc_video(ffmpeg, dir, n_out, fps, video) != 0)
                rc = 1;
            else
                printf("video: %s (%u frames at %d frames/s)\n", video, n_out, fps);
        }
        if (html != NULL)
            printf("page: %s (%lld bytes, %u frames)\n", html, html_bytes, (unsigned)rep.n);
    }
    duel_replay_free(&rep);
    if (fflush(stdout) != 0 && rc == 0) {
        fprintf(stderr, "duel_evolve: render: cannot write the output: %s\n", strerror(errno));
        rc = 1;
    }
    return rc;
}

/* ---- render-net ----------------------------------------------------------- */

int duel_cmd_render_net(int argc, char **argv)
{
    const char *blob = NULL, *out = NULL;
    char out_target[DUEL_RC_PATH];
    char dot[DUEL_RC_PATH], tmp_dot[DUEL_RC_PATH], tmp_png[DUEL_RC_PATH], a1[DUEL_RC_PATH + 2], a2[DUEL_RC_PATH + 4];
    char msg[512], *text = NULL, *dargv[6];
    size_t text_len = 0;
    FILE *f;
    duel_dot_opts o = {0};
    int i, fd, st, rc = 0, force = 0;

    for (i = 0; i < argc; i++) {
        if (strcmp(argv[i], "--force") == 0) {
            force = 1;
        } else if (strcmp(argv[i], "--out") == 0) {
            if (i + 1 >= argc) {
                fprintf(stderr, "duel_evolve: render-net: --out needs a file name\n");
                return 2;
            }
            out = argv[++i];
        } else if (strcmp(argv[i], "--min-weight") == 0) {
            if (i + 1 >= argc) {
                fprintf(stderr, "duel_evolve: render-net: --min-weight needs a value\n");
                return 2;
            }
            if (duel_dot_parse_min_weight("render-net", argv[++i], &o) != 0)
                return 2;
        } else if (argv[i][0] == '-' || blob != NULL) {
            fprintf(stderr, "usage: duel_evolve render-net BLOB --out FILE.png [--force] [--min-weight W]\n");
            return 2;
        } else {
            blob = argv[i];
        }
    }
    if (blob == NULL || out == NULL) {
        fprintf(stderr, "usage: duel_evolve render-net BLOB --out FILE.png [--force] [--min-weight W]\n");
        return 2;
    }
    if (duel_exec_find("dot", dot, sizeof dot) != 0) {
        fprintf(stderr, "duel_evolve: render-net: needs Graphviz dot, which is not on PATH (Debian: apt-get install "
                        "graphviz)\n");
        return 2;
    }
    if (duel_out_allowed("render-net", "--out", out, &duel_rc_net_kind, force, &blob, 1) != 0 ||
        duel_rc_target("render-net", out, out_target, "picture") != 0)
        return 2;
    out = out_target;
    /* the picture in memory first: a bad blob is reported before any file is made */
    f = open_memstream(&text, &text_len);
    if (f == NULL) {
        fprintf(stderr, "duel_evolve: render-net: out of memory\n");
        return 1;
    }
    if (duel_dot_blob(f, blob, &o) != 0) {
        fclose(f);
        free(text);
        return 2;
    }
    if (fclose(f) != 0) {
        fprintf(stderr, "duel_evolve: render-net: out of memory\n");
        free(text);
        return 1;
    }
    if (snprintf(tmp_dot, sizeof tmp_dot, "%s.dot.tmp", out) >= (int)sizeof tmp_dot ||
        snprintf(tmp_png, sizeof tmp_png, "%s.tmp", out) >= (int)sizeof tmp_png) {
        fprintf(stderr, "duel_evolve: render-net: %s: name too long\n", duel_esc(out));
        free(text);
        return 2;
    }
    fd = duel_tmp_create(tmp_dot);
    if (fd < 0 || (f = fdopen(fd, "w")) == NULL) {
        fprintf(stderr, "duel_evolve: render-net: %s: cannot write: %s\n", duel_esc(out), strerror(errno));
        if (fd >= 0) {
            close(fd);
            remove(tmp_dot);
        }
        free(text);
        return 2;
    }
    st = fwrite(text, 1, text_len, f) == text_len;
    free(text);
    if (fclose(f) != 0 || !st) {
        fprintf(stderr, "duel_evolve: render-net: %s: write failed: %s\n", duel_esc(out), strerror(errno));
        remove(tmp_dot);
        return 1;
    }
    snprintf(a1, sizeof a1, "-o%s", tmp_png);
    dargv[0] = (char *)"dot";
    dargv[1] = (char *)"-Tpng";
    dargv[2] = a1;
    dargv[3] = (char *)duel_rc_arg(tmp_dot, a2, sizeof a2);
    dargv[4] = NULL;
    st = duel_exec_run(dot, dargv, msg, sizeof msg);
    remove(tmp_dot);
    if (st != 0) {
        if (st > 0)
            fprintf(stderr, "duel_evolve: render-net: %s: dot failed (exit status %d)%s%s\n", duel_esc(out), st,
                    msg[0] ? ": " : "", duel_esc_msg(msg));
        else
            fprintf(stderr, "duel_evolve: render-net: %s: %s\n", duel_esc(out), duel_esc_msg(msg));
        rc = 1;
    } else if (duel_rc_mark_png(tmp_png) != 0 || duel_file_sync(tmp_png) != 0 || duel_file_commit(tmp_png, out) != 0) {
        fprintf(stderr, "duel_evolve: render-net: %s: cannot write: %s\n", duel_esc(out), strerror(errno));
        rc = 1;
    }
    if (rc != 0)
        remove(tmp_png);
    return rc;
}
