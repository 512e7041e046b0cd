# Issue 7: time per step of the nonlinear forced response (Google Benchmark).
add_executable(bench_multibody_dynamics ${CMAKE_CURRENT_LIST_DIR}/bench_dynamics.cpp)
target_link_libraries(bench_multibody_dynamics PRIVATE multibody benchmark::benchmark
                      benchmark::benchmark_main)
