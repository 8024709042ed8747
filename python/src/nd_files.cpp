// nd_files.cpp - the package's file reads and writes: bounded reads of regular files, and writes through
// duel_evolve's writer (duel_files.c), so that an interrupted save never leaves half a file in place of a whole one.
#include <cerrno>
#include <cstdio>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

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
    int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0)
        nd_os_error(path, "cannot open");
    struct stat st;
    if (fstat(fd, &st) != 0) {
        int e = errno;
        close(fd);
        errno = e;
        nd_os_error(path, "cannot read");
    }
    if (!S_ISREG(st.st_mode)) {
        close(fd);
        throw nd_error(NEAT_E_FORMAT, path + ": not a regular file", path);
    }
    if ((unsigned long long)st.st_size > cap) {
        close(fd);
        throw nd_error(NEAT_E_FORMAT,
                       path + ": " + std::to_string((long long)st.st_size) + " bytes, more than the " +
                           std::to_string((unsigned long long)cap) + " this kind of file may have",
                       path);
    }
    std::vector<uint8_t> buf((size_t)st.st_size);
    size_t done = 0;
    while (done < buf.size()) {
        ssize_t r = read(fd, buf.data() + done, buf.size() - done);
        if (r < 0 && errno == EINTR)
            continue;
        if (r < 0) {
            int e = errno;
            close(fd);
            errno = e;
            nd_os_error(path, "cannot read");
        }
        if (r == 0)
            break; // it shrank meanwhile: what is there
        done += (size_t)r;
    }
    buf.resize(done);
    close(fd);
    return buf;
}
