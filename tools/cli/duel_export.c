/* duel_export.c - `duel_evolve export BLOB --c-array NAME [-o FILE]`: a champion blob, validated by the runtime, as a C array a firmware links; `export --world SPEC`: a world's rules as their canonical bytes, the same way. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "duel_cli.h"
#include "duel_ctrl.h"
#include "duel_export_c.h"
#include "duel_files.h"
#include "duel_outputs.h"
#include "duel_world_cfg.h"
#include "duel_text.h"

static void duel_export_usage(void)
{
    fprintf(stderr, "usage: duel_evolve export BLOB --c-array NAME [-o FILE.c] [--header FILE.h] | export --world "
                    "NAME|FILE (--c-array NAME [-o FILE.c] | --raw -o FILE) [--force]\n");
}

int duel_cmd_export(int argc, char **argv)
{
    duel_export x;
    const char *blob = NULL, *out = NULL, *world = NULL;
    int i, rc = 0, raw = 0, force = 0;
    const char *in[3];

    memset(&x, 0, sizeof x);
    for (i = 0; i < argc; i++) {
        if (strcmp(argv[i], "--c-array") == 0 || strcmp(argv[i], "-o") == 0 || strcmp(argv[i], "--header") == 0 ||
            strcmp(argv[i], "--world") == 0) {
            if (i + 1 >= argc) {
                fprintf(stderr, "duel_evolve: export: %s needs a value\n", duel_esc(argv[i]));
                return 2;
            }
            if (argv[i][1] == 'o')
                out = argv[++i];
            else if (argv[i][2] == 'h')
                x.header = argv[++i];
            else if (argv[i][2] == 'w')
                world = argv[++i];
            else
                x.name = argv[++i];
        } else if (strcmp(argv[i], "--raw") == 0) {
            raw = 1;
        } else if (strcmp(argv[i], "--force") == 0) {
            force = 1;
        } else if (argv[i][0] == '-' || blob != NULL) {
            duel_export_usage();
            return 2;
        } else {
            blob = argv[i];
        }
    }
    if (world != NULL) {
        duel_export_world w;
        if (blob != NULL || x.header != NULL || raw == (x.name != NULL) || (raw && out == NULL)) {
            duel_export_usage();
            return 2;
        }
        if (!raw && !duel_export_name_ok(x.name)) {
            fprintf(stderr, "duel_evolve: export: '%s' is not a C identifier of at most %d characters (nor a "
                            "keyword)\n", duel_esc(x.name), DUEL_EXPORT_NAME_MAX);
            return 2;
        }
        w.name = x.name;
        in[0] = world;
        if (out != NULL && duel_out_allowed("export", "-o", out, raw ? &duel_export_raw_kind : &duel_export_c_kind,
                                            force, in, 1) != 0)
            return 2;
        if (duel_world_arg(&w.r, world) != 0 || duel_rules_encode(&w.r, w.b) != DUEL_OK)
            return 2;
        if (raw)
            return duel_file_write_with(out, duel_export_raw_cb, &w);
        if (out != NULL)
            return duel_file_write_with(out, duel_export_world_cb, &w);
        duel_export_world_write(stdout, w.name, &w.r, w.b);
        return 0;
    }
    if (blob == NULL || x.name == NULL) {
        duel_export_usage();
        return 2;
    }
    if (!duel_export_name_ok(x.name)) {
        fprintf(stderr, "duel_evolve: export: '%s' is not a C identifier of at most %d characters (nor a keyword)\n",
                duel_esc(x.name), DUEL_EXPORT_NAME_MAX);
        return 2;
    }
    /* before anything is written: never over the blob, the other output or a file that is not an export */
    in[0] = blob;
    in[1] = x.header;
    if (out != NULL && duel_out_allowed("export", "-o", out, &duel_export_c_kind, force, in, 2) != 0)
        return 2;
    in[1] = out;
    if (x.header != NULL && duel_out_allowed("export", "--header", x.header, &duel_export_c_kind, force, in, 2) != 0)
        return 2;
    {
        char msg[4600];
        if (duel_export_open_msg(&x, blob, msg, sizeof msg) != 0) {
            fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(msg));
            return 2;
        }
    }
    if (x.header != NULL)
        rc = duel_file_write_with(x.header, duel_export_write_header_cb, &x);
    if (rc != 0) {
        /* the header's one line said why */
    } else if (out != NULL) {
        rc = duel_file_write_with(out, duel_export_write_cb, &x);
    } else {
        duel_export_write_cb(stdout, &x); /* a failing stdout: duel_evolve.c says so */
    }
    free(x.blob);
    return rc;
}
