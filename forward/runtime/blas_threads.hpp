#pragma once
// Which BLAS sits behind libblas.so.3 (Debian's alternative), as far as calling it from two
// threads at once is concerned (docs/design/dependencies.md, BLAS). Debian 12 ships OpenBLAS in three
// builds: the serial one (libopenblas0-serial) is not safe for concurrent calls -- two CHOLMOD
// factorisations side by side corrupted each other's scratch buffers and reported "not positive
// definite" -- while the OpenMP and pthreads builds lock their buffers. ATLAS and the reference
// BLAS keep no shared state. Probed once through openblas_get_parallel (dlsym, so no link-time
// dependency on OpenBLAS); the pthreads build is also told to use one thread per call, so that
// its own pool never competes with spifit's OpenMP threads.
namespace spifit::runtime {

// True unless the BLAS is the serial OpenBLAS build.
bool blas_allows_concurrent_calls();
// "OpenBLAS (serial)", "OpenBLAS (pthreads)", "OpenBLAS (OpenMP)" or "not OpenBLAS".
const char* blas_description();

}  // namespace spifit::runtime
