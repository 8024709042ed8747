/* fw_libc.c - the only two C library functions the runtime and duelsim need, for images linked without a C library. */
#include <stddef.h>

/* Plain byte loops. Compiled with -fno-builtin and
 * -fno-tree-loop-distribute-patterns (CMakeLists.txt) so the compiler does
 * not turn them back into calls to themselves. */
void *memcpy(void *dst, const void *src, size_t n);
void *memset(void *dst, int c, size_t n);

void *memcpy(void *dst, const void *src, size_t n)
{
    unsigned char *d = (unsigned char *)dst;
    const unsigned char *s = (const unsigned char *)src;
    while (n-- > 0)
        *d++ = *s++;
    return dst;
}

void *memset(void *dst, int c, size_t n)
{
    unsigned char *d = (unsigned char *)dst;
    while (n-- > 0)
        *d++ = (unsigned char)c;
    return dst;
}
