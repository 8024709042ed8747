# bench_eval.cmake - the static library bencheval: the tasks' per-network evaluators (bench_eval.h) and the cart,
# for neat_bench and for the NEAT C++ harness (tools/neatcpp), which may be configured without the tools; the first
# directory that includes this file defines it.
if(NOT TARGET bencheval)
  add_library(bencheval STATIC ${CMAKE_CURRENT_LIST_DIR}/bench_eval.c ${CMAKE_CURRENT_LIST_DIR}/cartpole.c)
  target_include_directories(bencheval PUBLIC ${CMAKE_CURRENT_LIST_DIR})
  # the flags neat_bench compiled the evaluators with before they moved here: the same doubles
  target_compile_options(bencheval PRIVATE ${NEAT_WARNINGS} ${NEAT_FP})
  target_link_libraries(bencheval PUBLIC neat m)
endif()
