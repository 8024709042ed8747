// nd_files.cpp - the package's file reads and writes through duel_evolve's reader and writer (duel_files.c): bounded
// reads of regular files, and writes that an interruption never leaves half done in place of a whole file.
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>


#include <nanobind/stl/string.h>

#include "nd.h"
extern "C" {
#include "duel_files.h"
}

[[noreturn]] static void nd_os_error(const std::string &path, const char *what)
{
    int e = errno;
    // OSError(errno, strerror, filename): Python picks FileNotFoundError, IsADirectoryError, ... from errno
    PyErr_SetObject(PyExc_OSError, nb::make_tuple(e, std::string(what) + ": " + std::strerror(e), path).ptr());
    throw nb::python_error();
}

void nd_write_file(const std::string &path, const uint8_t *bytes, size_t len)
{
    // duel_evolve's one writer: a temporary file of its own beside path, fsync, rename, the directory synced
    int r;
    {
        nb::gil_scoped_release nogil;
        r = duel_file_replace(path.c_str(), bytes, len);
    }
    if (r != 0)
        nd_os_error(path, "cannot write");
}

std::vector<uint8_t> nd_read_file(const std::string &path, size_t cap)
{
    // duel_evolve's one reader (duel_files.c): bounded, regular files only (a FIFO or a device is never waited on)
    uint8_t *data = nullptr;
    size_t len = 0;
    int r;
    {
        nb::gil_scoped_release nogil;
        r = duel_file_read(path.c_str(), cap, &data, &len);
    }
    if (r == -1)
        nd_os_error(path, "cannot open");
    if (r != 0 && (errno == DUEL_ENOTREG || errno == EISDIR))
        throw nd_error(NEAT_E_FORMAT, path + ": not a regular file", path);
    if (r != 0 && errno == EFBIG)
        throw nd_error(NEAT_E_FORMAT,
                       path + ": more than the " + std::to_string((unsigned long long)cap) +
                           " bytes this kind of file may have",
                       path);
    if (r != 0)
        nd_os_error(path, "cannot read");
    std::vector<uint8_t> buf(data, data + len);
    std::free(data);
    return buf;
}
