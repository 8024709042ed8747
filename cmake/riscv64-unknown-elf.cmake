# Toolchain for bare-metal 32-bit RISC-V (Debian gcc-riscv64-unknown-elf, whose multilibs include
# rv32imac/ilp32). -DNEAT_RISCV_ARCH=rv32imac (default) and -DNEAT_RISCV_ABI=ilp32 pick the target.
# Like the Arm file: -ffreestanding; the runtime and duelsim link nothing from a C library but memcpy
# and memset (docs/firmware.md). Debian's riscv64 gcc ships no C library at all, so the headers
# (<string.h> declares those two) come from picolibc (Debian picolibc-riscv64-unknown-elf).
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR riscv32)
set(CMAKE_C_COMPILER riscv64-unknown-elf-gcc)
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES NEAT_RISCV_ARCH NEAT_RISCV_ABI)
if(NOT NEAT_RISCV_ARCH)
  set(NEAT_RISCV_ARCH rv32imac)
endif()
if(NOT NEAT_RISCV_ABI)
  set(NEAT_RISCV_ABI ilp32)
endif()
set(NEAT_RISCV_LIBC_INCLUDE /usr/lib/picolibc/riscv64-unknown-elf/include)
if(NOT EXISTS ${NEAT_RISCV_LIBC_INCLUDE}/string.h)
  message(FATAL_ERROR "no C library headers for riscv64-unknown-elf in ${NEAT_RISCV_LIBC_INCLUDE} "
                      "(apt-get install picolibc-riscv64-unknown-elf)")
endif()
set(CMAKE_C_FLAGS_INIT "-march=${NEAT_RISCV_ARCH} -mabi=${NEAT_RISCV_ABI} -ffreestanding -ffunction-sections \
-fdata-sections -isystem ${NEAT_RISCV_LIBC_INCLUDE}")
# the NEAT_RUNTIME_ONLY build prints the library sizes with this
set(NEAT_SIZE riscv64-unknown-elf-size CACHE FILEPATH "size for the target")
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
