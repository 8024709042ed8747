/* neat_duel_version.h - the project's version (the one place it is written) and the public API's export attribute. */
#ifndef NEAT_DUEL_VERSION_H
#define NEAT_DUEL_VERSION_H

/*
 * The top CMakeLists.txt reads these three lines (file(STRINGS)) for
 * project(VERSION): the libraries' VERSION/SOVERSION, the CMake package's
 * version file, the pkg-config files' Version and duel_evolve --version all
 * come from here. Bump them here only. (The file formats have versions of
 * their own: NRT_FORMAT_VERSION, NEAT_CHECKPOINT_VERSION.)
 */
#define NEAT_DUEL_VERSION_MAJOR 0
#define NEAT_DUEL_VERSION_MINOR 16
#define NEAT_DUEL_VERSION_PATCH 0

#define NEAT_DUEL_STR_(x) #x
#define NEAT_DUEL_STR(x) NEAT_DUEL_STR_(x)
#define NEAT_DUEL_VERSION_STRING                                                                                 \
    NEAT_DUEL_STR(NEAT_DUEL_VERSION_MAJOR)                                                                       \
    "." NEAT_DUEL_STR(NEAT_DUEL_VERSION_MINOR) "." NEAT_DUEL_STR(NEAT_DUEL_VERSION_PATCH)

/*
 * Shared libraries are compiled with -fvisibility=hidden, so only what the
 * public headers declare is exported: NRT_API, NEAT_API and DUEL_API (each
 * header's) expand to this. NEAT_DUEL_SHARED is defined for the libraries
 * and their users by a BUILD_SHARED_LIBS build (CMake target, pkg-config
 * Cflags). Static and firmware builds leave it empty: nothing to export.
 */
#if defined(NEAT_DUEL_SHARED) && (defined(__GNUC__) || defined(__clang__))
#define NEAT_DUEL_EXPORT __attribute__((visibility("default")))
#else
#define NEAT_DUEL_EXPORT
#endif

#endif /* NEAT_DUEL_VERSION_H */
