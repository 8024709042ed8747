/* fw_semihosting.c - console output and exit over semihosting, for every target port (each gives fw_semihost, its trap). */
#include "fw_port.h"

/* Semihosting operations (Arm "Semihosting for AArch32 and AArch64", v2;
 * the RISC-V semihosting spec reuses them). */
#define FW_SYS_WRITE0 0x04
#define FW_SYS_EXIT 0x18          /* angel_SWIreason_ReportException */
#define FW_SYS_EXIT_EXTENDED 0x20 /* the same, with an exit status */
#define FW_ADP_STOPPED_APPLICATION_EXIT 0x20026u
#define FW_ADP_STOPPED_RUNTIME_ERROR_UNKNOWN 0x20023u

void fw_port_write(const char *s, size_t n)
{
    /* SYS_WRITE0 takes a NUL-terminated string: chunks of a small buffer */
    char buf[65];
    size_t i = 0;
    while (i < n) {
        size_t k = 0;
        while (k < sizeof buf - 1 && i < n)
            buf[k++] = s[i++];
        buf[k] = '\0';
        fw_semihost(FW_SYS_WRITE0, buf);
    }
}

void fw_port_exit(int status)
{
    uint32_t block[2];
    block[0] = FW_ADP_STOPPED_APPLICATION_EXIT;
    block[1] = (uint32_t)status;
    fw_semihost(FW_SYS_EXIT_EXTENDED, block);
    /* a host without SYS_EXIT_EXTENDED: plain SYS_EXIT, success or not */
    fw_semihost(FW_SYS_EXIT, (const void *)(status == 0 ? FW_ADP_STOPPED_APPLICATION_EXIT
                                                        : FW_ADP_STOPPED_RUNTIME_ERROR_UNKNOWN));
    for (;;)
        __asm__ volatile("wfi");
}
