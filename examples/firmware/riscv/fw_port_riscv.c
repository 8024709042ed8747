/* fw_port_riscv.c - the RISC-V port: the semihosting trap, minstret as the counter, the calibration loop. */
#include "fw_port.h"
#include "fw_riscv.h"

const uint32_t fw_port_counter_mask = 0xFFFFFFFFu;

/* A semihosting call: the uncompressed sequence slli x0,x0,0x1f; ebreak;
 * srai x0,x0,7 (within one page: 16-byte aligned), operation in a0,
 * argument in a1, result in a0. */
uint32_t fw_semihost(uint32_t op, const void *arg)
{
    register uint32_t a0 __asm__("a0") = op;
    register const void *a1 __asm__("a1") = arg;
    __asm__ volatile(".option push\n"
                     ".option norvc\n"
                     ".balign 16\n"
                     "slli zero, zero, 0x1f\n"
                     "ebreak\n"
                     "srai zero, zero, 7\n"
                     ".option pop\n"
                     : "+r"(a0)
                     : "r"(a1)
                     : "memory");
    return a0;
}

void fw_port_counter_start(void)
{
    /* minstret and mcycle run from reset */
}

uint32_t fw_port_counter(void)
{
    uint32_t v;
    __asm__ volatile(FW_ZICSR("csrr %0, minstret") : "=r"(v));
    return v;
}

int fw_port_cycles(uint32_t *value)
{
    __asm__ volatile(FW_ZICSR("csrr %0, mcycle") : "=r"(*value));
    return 0;
}

void fw_port_spin(uint32_t n)
{
    /* two instructions per iteration: addi, bnez */
    __asm__ volatile("1: addi %0, %0, -1\n"
                     "   bnez %0, 1b\n"
                     : "+r"(n));
}
