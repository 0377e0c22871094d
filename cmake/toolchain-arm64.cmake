# 64-bit Arm (Raspberry Pi 3/4/5 with a 64-bit OS): cmake --preset arm64 (build/arm64).
set(TACTUS_CROSS_TRIPLET aarch64-linux-gnu)
set(TACTUS_CROSS_PROCESSOR aarch64)
set(TACTUS_QEMU qemu-aarch64-static)
include(${CMAKE_CURRENT_LIST_DIR}/toolchain-debian-cross.cmake)
