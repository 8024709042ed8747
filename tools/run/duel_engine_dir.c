/* duel_engine_dir.c - the run directory: its lock, the refusal of a directory that is not a run's, config.ini and the seal that tells the run's writing from a hand edit. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "duel_cmp_cache.h"
#include "duel_engine_internal.h"
#include "duel_files.h"
#include "duel_generations.h"
#include "duel_outputs.h"
#include "duel_text.h"

/* config.ini's seal: its second line holds the FNV-1a hash of every line after it, so that resume tells the
 * run's own writing from a hand edit of any key ([run]'s generations and strength_every, which the checkpoint does
 * not hold, included). */
#define DUEL_SEAL_TAIL ": written by the run (a hand edit is refused by resume; give a change as resume --set KEY=VALUE)\n"
/* what the seal records: the [run] keys the checkpoint does not hold, so that an edit of one is named */
#define DUEL_SEAL_KEYS "; generations = %u, strength_every = %u\n"

/* config.ini, sealed, replaced atomically. 0, or -1 after one line. */
int de_write_config(duel_engine *R)
{
    char path[4200], *text = NULL, *body = NULL;
    size_t len = 0, blen = 0;
    FILE *mem = open_memstream(&body, &blen);
    int r;
    if (mem == NULL)
        return -1;
    duel_config_dump(mem, &R->cfg);
    if (fclose(mem) != 0) {
        free(body);
        return -1;
    }
    mem = open_memstream(&text, &len);
    if (mem == NULL) {
        free(body);
        return -1;
    }
    fprintf(mem, DUEL_RUN_CONFIG_MARK " (duel_evolve config --dump format)\n");
    fprintf(mem, DUEL_SEAL "%016llx" DUEL_SEAL_TAIL, (unsigned long long)duel_blob_hash((const uint8_t *)body, blen));
    fprintf(mem, DUEL_SEAL_KEYS, R->cfg.generations, R->cfg.strength_every);
    fwrite(body, 1, blen, mem);
    free(body);
    if (fclose(mem) != 0) {
        free(text);
        return -1;
    }
    de_path(path, sizeof path, R->dir, "config.ini");
    r = duel_file_replace(path, text, len);
    if (r != 0)
        de_err(R, "%s: cannot write: %s\n", de_esc(R, path), strerror(errno));
    free(text);
    return r;
}
/* One process per run directory: a second run or resume there is refused. */
int de_take_lock(duel_engine *R, const char *dir)
{
    if (duel_dir_lock(dir, &R->lock) == 0)
        return 0;
    if (errno == EWOULDBLOCK)
        de_err(R, "%s is in use by another duel_evolve run or resume\n", de_esc(R, dir));
    else if (errno == ELOOP)
        de_err(R, "%s/.lock is a symbolic link: refusing to follow it (remove it)\n", de_esc(R, dir));
    else
        de_err(R, "%s/.lock: cannot open: %s\n", de_esc(R, dir), strerror(errno));
    return -1;
}

/* A run directory without a checkpoint: a run that died during generation
 * 0 may have recorded that generation's rows and blob (they are redone), but
 * anything of a later generation means a checkpoint existed and is gone:
 * starting over (run) or from generation 0 (resume) would discard or mix
 * what was recorded, so such a directory is refused. 1 (what in msg), or 0. */
int de_has_history(const char *dir, char *msg, size_t cap)
{
    char path[4200];
    uint8_t *data;
    size_t len, i;
    unsigned long rows = 0, blobs = 0;
    DIR *d;
    struct dirent *e;
    de_path(path, sizeof path, dir, "generations.csv");
    if (duel_file_read(path, DUEL_GENERATIONS_MAX_FILE, &data, &len) == 0) {
        /* rows whose generation (the first field) is not 0 */
        for (i = 0; i < len; i++)
            if ((i == 0 || data[i - 1] == '\n') && data[i] >= '0' && data[i] <= '9' &&
                !(data[i] == '0' && i + 1 < len && data[i + 1] == ','))
                rows++;
        free(data);
    }
    de_path(path, sizeof path, dir, "champions");
    d = opendir(path);
    if (d != NULL) {
        while ((e = readdir(d)) != NULL) {
            size_t n = strlen(e->d_name);
            blobs += n > 5 && strcmp(e->d_name + n - 5, ".blob") == 0 && strcmp(e->d_name, "gen-00000.blob") != 0;
        }
        closedir(d);
    }
    if (rows == 0 && blobs == 0)
        return 0;
    snprintf(msg, cap, "%lu rows of generations.csv and %lu champion blobs of generations after 0", rows, blobs);
    return 1;
}

/* 1 when dir/name is an empty directory. */
static int duel_empty_dir(const char *dir, const char *name)
{
    char path[4200];
    DIR *d;
    struct dirent *e;
    int empty = 1;
    de_path(path, sizeof path, dir, name);
    if ((d = opendir(path)) == NULL)
        return 0;
    while (empty && (e = readdir(d)) != NULL)
        empty = strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0;
    closedir(d);
    return empty;
}

/* Whether an existing directory may become a new run: empty, or a run's own
 * files only, with a config.ini (if any) that a run wrote. 1, or 0 with the
 * first foreign entry in what. */
static int duel_dir_is_runs(const char *dir, char *what, size_t cap)
{
    char path[4200], first[300] = "";
    DIR *d = opendir(dir);
    struct dirent *e;
    uint8_t *text;
    size_t len;
    int ok = 1;
    if (d == NULL) {
        snprintf(what, cap, "cannot be listed: %s", strerror(errno));
        return 0;
    }
    while (ok && (e = readdir(d)) != NULL) {
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
            continue;
        if (!duel_is_run_file(e->d_name)) {
            char esc[1100];
            snprintf(what, cap, "holds '%s', which is not a run's", duel_text_escape(e->d_name, esc, sizeof esc));
            ok = 0;
        } else if (first[0] == '\0' && strcmp(e->d_name, ".lock") != 0 && strcmp(e->d_name, "config.ini.tmp") != 0 &&
                   !duel_empty_dir(dir, e->d_name)) {
            snprintf(first, sizeof first, "%s", e->d_name);
        }
    }
    closedir(d);
    de_path(path, sizeof path, dir, "config.ini");
    /* a run writes config.ini before anything else it keeps: files of a run's names without it are someone
     * else's (a user's generations.csv) */
    if (ok && first[0] != '\0' && access(path, F_OK) != 0) {
        char esc[1100];
        snprintf(what, cap, "holds '%s' but no config.ini of a run", duel_text_escape(first, esc, sizeof esc));
        ok = 0;
    }
    if (ok && duel_file_read(path, 1u << 20, &text, &len) == 0) {
        static const char mark[] = DUEL_RUN_CONFIG_MARK;
        ok = len >= sizeof mark - 1 && memcmp(text, mark, sizeof mark - 1) == 0;
        if (!ok)
            snprintf(what, cap, "holds a config.ini that a run did not write");
        free(text);
    } else if (ok && errno != ENOENT) {
        snprintf(what, cap, "config.ini: %s", duel_file_strerror(errno));
        ok = 0;
    }
    return ok;
}

/* A new run's directory: created and locked, refused when it holds a run,
 * the records of one or anything not a run's, cleared of a run that died
 * before its first checkpoint, with config.ini written. 0, or the exit
 * status after one line. */
int de_prepare_dir(duel_engine *R)
{
    static const char *const files[] = {"generations.csv", "dominance.csv", "strength.csv"};
    char err[600], path[4200];
    struct stat st;
    int i;
    /* looked at before anything is created in it, and again under the lock */
    if (stat(R->dir, &st) == 0 && S_ISDIR(st.st_mode) && !duel_dir_is_runs(R->dir, err, sizeof err)) {
        de_err(R, "%s is not empty and not a run directory (it %s): choose another --out\n",
                de_esc(R, R->dir), de_esc_msg(R, err));
        return 2;
    }
    if (duel_mkdir(R->dir) != 0) {
        de_err(R, "%s: cannot create: %s\n", de_esc(R, R->dir), strerror(errno));
        return 2;
    }
    if (de_take_lock(R, R->dir) != 0)
        return 2;
    if (!duel_dir_is_runs(R->dir, err, sizeof err)) {
        de_err(R, "%s is not empty and not a run directory (it %s): choose another --out\n",
                de_esc(R, R->dir), de_esc_msg(R, err));
        return 2;
    }
    de_path(path, sizeof path, R->dir, "champions");
    if (duel_mkdir(path) != 0) {
        de_err(R, "%s: cannot create: %s\n", de_esc(R, path), strerror(errno));
        return 2;
    }
    de_path(path, sizeof path, R->dir, "checkpoint.bin");
    if (stat(path, &st) == 0) { /* checked under the lock: two runs cannot both pass */
        de_err(R, "%s already holds a run: resume it with duel_evolve resume %s, or choose "
                        "another --out\n", de_esc(R, R->dir), de_esc(R, R->dir));
        return 2;
    }
    de_path(path, sizeof path, R->dir, "games");
    if (R->record_games && duel_mkdir(path) != 0) {
        de_err(R, "%s: cannot create: %s\n", de_esc(R, path), strerror(errno));
        return 2;
    }
    /* a directory left by a run that died before its first checkpoint starts over; one whose checkpoint
     * is gone but whose generations are recorded is not overwritten */
    if (de_has_history(R->dir, err, sizeof err)) {
        de_err(R, "%s has no checkpoint.bin but holds %s: refusing to overwrite them (restore "
                        "the checkpoint and resume, or choose another --out)\n", de_esc(R, R->dir), de_esc_msg(R, err));
        return 2;
    }
    for (i = 0; i < 3; i++) {
        de_path(path, sizeof path, R->dir, files[i]);
        unlink(path);
    }
    /* config.ini first: it is what marks the directory as a run's if this is killed before the rest */
    if (de_write_config(R) != 0)
        return 1;
    return de_copy_opponents(R) != 0 ? 1 : 0;
}

/* Whether dir/config.ini is as the run wrote it: 1 (its seal holds), 0 (no seal: a run from before it, whose
 * [run] keys cannot be checked), -1 (edited since: the seal does not hold, or the file cannot be read). With a
 * seal, *gens and *every are the values the run wrote. */
int de_config_sealed(const char *dir, uint32_t *gens, uint32_t *every)
{
    char path[4200];
    uint8_t *text;
    size_t len, a, b, c;
    unsigned long long want;
    unsigned g, e;
    int r;
    de_path(path, sizeof path, dir, "config.ini");
    if (duel_file_read(path, 1u << 20, &text, &len) != 0)
        return -1;
    for (a = 0; a < len && text[a] != '\n'; a++)
        ;
    a++; /* the second line: the checksum; the third: the keys */
    if (a + strlen(DUEL_SEAL) + 16 > len || memcmp(text + a, DUEL_SEAL, strlen(DUEL_SEAL)) != 0) {
        free(text);
        return 0;
    }
    for (b = a; b < len && text[b] != '\n'; b++)
        ;
    for (c = b + 1; c < len && text[c] != '\n'; c++)
        ;
    r = -1;
    if (c < len && sscanf((const char *)text + a + strlen(DUEL_SEAL), "%16llx", &want) == 1 &&
        sscanf((const char *)text + b + 1, "; generations = %u, strength_every = %u", &g, &e) == 2) {
        *gens = g;
        *every = e;
        r = duel_blob_hash(text + c + 1, len - c - 1) == (uint64_t)want ? 1 : -1;
    }
    free(text);
    return r;
}

