# Shared by toolchain-arm64.cmake and toolchain-armhf.cmake: cross-building on Debian 12 with its
# cross compiler (crossbuild-essential-ARCH) and the multiarch -dev packages (libsndfile1-dev:ARCH
# and so on, scripts/setup.sh --arm), the target's programs run by qemu-user-static: the
# build-time generators (FIR tables, FFTW wisdom, both computed as on the board) and ctest's tests.
# Set before including: TACTUS_CROSS_TRIPLET (aarch64-linux-gnu), TACTUS_CROSS_PROCESSOR, TACTUS_QEMU.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR ${TACTUS_CROSS_PROCESSOR})
set(CMAKE_C_COMPILER ${TACTUS_CROSS_TRIPLET}-gcc)
set(CMAKE_CXX_COMPILER ${TACTUS_CROSS_TRIPLET}-g++)
# GCC's note that passing std::pair changed in GCC 10.1 concerns code built by older GCCs only.
set(CMAKE_CXX_FLAGS_INIT -Wno-psabi)
# Libraries and CMake packages from /usr/lib/TRIPLET only; headers-only packages (nlohmann-json,
# CLI11, readerwriterqueue, Pd's m_pd.h) from /usr/include and /usr/share as on the host.
set(CMAKE_LIBRARY_ARCHITECTURE ${TACTUS_CROSS_TRIPLET})
set(ENV{PKG_CONFIG_LIBDIR} /usr/lib/${TACTUS_CROSS_TRIPLET}/pkgconfig:/usr/share/pkgconfig)
set(ENV{PKG_CONFIG_PATH} "")
# The target's loader and libraries are installed in / by multiarch (libc6:ARCH): no -L needed.
set(CMAKE_CROSSCOMPILING_EMULATOR /usr/bin/${TACTUS_QEMU})
