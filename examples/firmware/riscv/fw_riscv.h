/* fw_riscv.h - what the RISC-V port's two files share: CSR instructions in inline assembly. */
#ifndef FW_RISCV_H
#define FW_RISCV_H

/* CSR instructions belong to the Zicsr extension, which -march=rv32imac no
 * longer names since the 2019 ISA split; every core this port runs on has it. */
#define FW_ZICSR(insn) ".option push\n.option arch, +zicsr\n" insn "\n.option pop\n"

#endif /* FW_RISCV_H */
