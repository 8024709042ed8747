/* duel_node_lcm.c - LCM instances for the nodes: created quietly, and handled without TCP's delayed ACKs stalling lockstep over tcpq://. */
#define _DEFAULT_SOURCE /* TCP_QUICKACK */
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <stdio.h>
#include <string.h>
#include <sys/socket.h>
#include <unistd.h>

#include "duel_node.h"

lcm_t *duel_node_lcm_create(const char *url)
{
    lcm_t *lcm;
    int saved, null_fd;
    fflush(stderr);
    saved = dup(2);
    null_fd = open("/dev/null", O_WRONLY);
    if (saved >= 0 && null_fd >= 0)
        dup2(null_fd, 2); /* "LCM tcpq: connecting..." and the like: the caller says what failed */
    lcm = lcm_create(url);
    if (saved >= 0) {
        fflush(stderr);
        dup2(saved, 2);
        close(saved);
    }
    if (null_fd >= 0)
        close(null_fd);
    if (lcm != NULL && strncmp(url, "tcpq://", 7) == 0 && lcm_get_fileno(lcm) < 0) {
        lcm_destroy(lcm); /* tcpq creates an unconnected instance when no hub answers */
        lcm = NULL;
    }
    return lcm;
}

int duel_node_handle(lcm_t *lcm, int timeout_ms)
{
    int fd = lcm_get_fileno(lcm), type = 0, one = 1;
    socklen_t len = sizeof type;
    if (fd >= 0 && getsockopt(fd, SOL_SOCKET, SO_TYPE, &type, &len) == 0 && type == SOCK_STREAM) {
        setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
#ifdef TCP_QUICKACK
        setsockopt(fd, IPPROTO_TCP, TCP_QUICKACK, &one, sizeof one);
#endif
    }
    return lcm_handle_timeout(lcm, timeout_ms);
}
