# tools.cmake - the tools' tests (included by tests/CMakeLists.txt when the tools are built): fuzzers, the
# tools' libraries, every duel_evolve command from the outside, LCM, MPI, --version.
# libFuzzer harnesses, one per decoder a user can feed bytes to (configure with CC=clang -DNEAT_FUZZ=ON, which
# instruments every library); seed corpora in fuzz/corpus/NAME, made by scripts/fuzz_corpus.sh;
# scripts/fuzz.sh SECONDS runs them all
if(NEAT_FUZZ)
  function(neat_add_fuzz name)
    add_executable(${name} fuzz/${name}.c ${ARGN})
    target_compile_options(${name} PRIVATE ${NEAT_WARNINGS})
    target_link_options(${name} PRIVATE -fsanitize=fuzzer)
    set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/tests)
  endfunction()
  neat_add_fuzz(fuzz_blob)
  target_link_libraries(fuzz_blob PRIVATE neat nrt)
  neat_add_fuzz(fuzz_pop)
  target_link_libraries(fuzz_pop PRIVATE neat)
  neat_add_fuzz(fuzz_genome)
  target_link_libraries(fuzz_genome PRIVATE neat nrt)
  neat_add_fuzz(fuzz_coev)
  target_link_libraries(fuzz_coev PRIVATE neat)
  neat_add_fuzz(fuzz_rules)
  target_link_libraries(fuzz_rules PRIVATE duelsim)
  neat_add_fuzz(fuzz_ini ${PROJECT_SOURCE_DIR}/tools/common/duel_config.c ${PROJECT_SOURCE_DIR}/bench/bench_config.c
                ${PROJECT_SOURCE_DIR}/tools/experiment/duel_plan.c ${PROJECT_SOURCE_DIR}/tools/common/duel_runtag.c)
  target_include_directories(fuzz_ini PRIVATE ${PROJECT_SOURCE_DIR}/bench ${PROJECT_SOURCE_DIR}/tools/experiment)
  target_link_libraries(fuzz_ini PRIVATE neattools duelfiles duelsim)
  neat_add_fuzz(fuzz_lcm_log ${PROJECT_SOURCE_DIR}/tools/cli/duel_log_cmd.c)
  target_include_directories(fuzz_lcm_log PRIVATE ${PROJECT_SOURCE_DIR}/tools/cli)
  target_link_libraries(fuzz_lcm_log PRIVATE duellcm duelfiles)
  neat_add_fuzz(fuzz_lcm_msg)
  target_link_libraries(fuzz_lcm_msg PRIVATE duellcm neat)
  neat_add_fuzz(fuzz_rundir)
  target_link_libraries(fuzz_rundir PRIVATE duelfiles)
  neat_add_fuzz(fuzz_mpi_wire ${PROJECT_SOURCE_DIR}/tools/mpi/duel_mpi_wire.c)
  target_include_directories(fuzz_mpi_wire PRIVATE ${PROJECT_SOURCE_DIR}/tools/mpi)
  target_link_libraries(fuzz_mpi_wire PRIVATE neattools duelsim nrt)

  neat_add_fuzz(fuzz_html)
  target_link_libraries(fuzz_html PRIVATE duelhtml)
  add_custom_target(fuzzers DEPENDS fuzz_blob fuzz_pop fuzz_genome fuzz_coev fuzz_rules fuzz_ini fuzz_lcm_log fuzz_lcm_msg fuzz_rundir
                  fuzz_mpi_wire fuzz_html)

  add_executable(make_corpus fuzz/make_corpus.c)
  target_compile_options(make_corpus PRIVATE ${NEAT_WARNINGS})
  target_link_libraries(make_corpus PRIVATE neat)
  set_target_properties(make_corpus PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/tests)
endif()

# the run directory's files read back (tools/common)
neat_add_test(tools test_dominance)
target_link_libraries(test_dominance PRIVATE duelfiles)
# the experiment's statistics (tools/experiment/duel_stats.c)
neat_add_test(tools test_stats)
target_link_libraries(test_stats PRIVATE duelstats)

# the statistics of the registered comparisons (scripts/neat_stats.py: docs/neat-cpp.md, docs/study2.md)
add_test(NAME tools/neat_stats COMMAND ${DUEL_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/tools/test_neat_stats.py)

# neat_bench from the outside (shell: exit codes, messages, thread independence)
foreach(check bad-config dump-roundtrip threads built-in affinity profile)
  add_test(NAME tools/neat_bench_${check}
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/tools/bench_cli.sh $<TARGET_FILE:neat_bench> ${check}
                   ${PROJECT_SOURCE_DIR}/bench)
  set_tests_properties(tools/neat_bench_${check} PROPERTIES SKIP_RETURN_CODE 77)
endforeach()

# duel_evolve play from the outside (exit codes, one-line errors, the trace's shape)
foreach(check bad-input trace compare)
  add_test(NAME tools/duel_play_${check}
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/tools/duel_cli.sh $<TARGET_FILE:duel_evolve> ${check})
endforeach()

# every command's --help and -h (each option of its synopsis described), options given last without a value
add_test(NAME tools/duel_help COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/tools/duel_help.sh $<TARGET_FILE:duel_evolve>)

# duel_evolve inspect and dot on duel_bench's blobs (counts, names, Graphviz edges, one-line errors)
foreach(check inspect dot generic bad-input)
  add_test(NAME tools/duel_inspect_${check}
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/tools/duel_inspect.sh $<TARGET_FILE:duel_evolve>
                   $<TARGET_FILE:duel_bench> ${check})
endforeach()

# duel_evolve run/resume/config (threads 1 = 2, kill -9 and Ctrl-C resumes, overrides, configuration errors)
# (threads, kill and interrupt on a smaller run under the sanitizers, where every game is ten times slower)
foreach(check threads kill interrupt overrides config ladder)
  set(NEAT_RUN_CFG ${CMAKE_CURRENT_SOURCE_DIR}/tools/coev-small.ini)
  if(NEAT_SANITIZE AND check MATCHES "^(threads|kill|interrupt)$")
    set(NEAT_RUN_CFG ${CMAKE_CURRENT_SOURCE_DIR}/tools/coev-small-asan.ini)
  endif()
  add_test(NAME tools/duel_run_${check}
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/tools/duel_run.sh $<TARGET_FILE:duel_evolve> ${check} ${NEAT_RUN_CFG})
endforeach()

# the world's rules as data: config.ini and checkpoint, bad rules, resume, the cache per world, the independent model
foreach(check config resume bad cache replay)
  add_test(NAME tools/world_${check}
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/tools/world.sh $<TARGET_FILE:duel_evolve> ${check}
                   ${CMAKE_CURRENT_SOURCE_DIR}/tools/coev-small.ini)
endforeach()

# evolution against fixed opponents: threads, kill -9 and resume, bad input, the strength series
foreach(check threads kill bad strength)
  add_test(NAME tools/fixed_${check}
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/tools/fixed.sh $<TARGET_FILE:duel_evolve> ${check})
endforeach()

# a run of configs/quick.ini with a fixed seed, byte for byte as recorded before the simulator's speed-ups
add_test(NAME tools/golden_quick
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/tools/golden_run.sh $<TARGET_FILE:duel_evolve> ${PROJECT_SOURCE_DIR}/configs/quick.ini
                 ${CMAKE_CURRENT_SOURCE_DIR}/tools/fixtures/golden-quick/sha256)

# the baselines of configs/ (start topologies, fixed and simplifying runs, random fitness) through the command line
foreach(check config fixed simplify best genome random)
  add_test(NAME tools/presets_${check}
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/tools/presets.sh $<TARGET_FILE:duel_evolve> ${PROJECT_SOURCE_DIR}/configs
                   ${check})
endforeach()
# duel_evolve experiment: bad plans; continuation after kill -9 and SIGINT = uninterrupted, the report recomputed
# in Python, bad directories; report of the committed fixture (tests/tools/fixtures/experiment-tiny). A smaller
# plan under the sanitizers, where every game is ten times slower.
if(NEAT_SANITIZE)
  set(NEAT_EXP_PLAN ${CMAKE_CURRENT_SOURCE_DIR}/tools/tiny-plan-asan.ini)
else()
  set(NEAT_EXP_PLAN ${CMAKE_CURRENT_SOURCE_DIR}/tools/tiny-plan.ini)
endif()
add_test(NAME tools/experiment_bad
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/tools/experiment.sh $<TARGET_FILE:duel_evolve>
                 ${CMAKE_CURRENT_SOURCE_DIR}/tools/tiny-plan.ini ${CMAKE_CURRENT_SOURCE_DIR}/tools/experiment_check.py bad)
add_test(NAME tools/experiment_resume
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/tools/experiment.sh $<TARGET_FILE:duel_evolve> ${NEAT_EXP_PLAN}
                 ${CMAKE_CURRENT_SOURCE_DIR}/tools/experiment_check.py resume)
add_test(NAME tools/experiment_report
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/tools/experiment.sh $<TARGET_FILE:duel_evolve>
                 ${CMAKE_CURRENT_SOURCE_DIR}/tools/tiny-plan.ini ${CMAKE_CURRENT_SOURCE_DIR}/tools/experiment_check.py
                 report ${CMAKE_CURRENT_SOURCE_DIR}/tools/fixtures/experiment-tiny)
set_tests_properties(tools/experiment_resume PROPERTIES TIMEOUT 900)

# the paper's performance measure against play --games 288, threads, cache, bad input (smaller runs under
# the sanitizers: 262 s there with coev-small.ini, 107 s with coev-small-asan.ini)
set(NEAT_CMP_CFG ${CMAKE_CURRENT_SOURCE_DIR}/tools/coev-small.ini)
if(NEAT_SANITIZE)
  set(NEAT_CMP_CFG ${CMAKE_CURRENT_SOURCE_DIR}/tools/coev-small-asan.ini)
endif()
add_test(NAME tools/compare COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/tools/compare.sh $<TARGET_FILE:duel_evolve> ${NEAT_CMP_CFG})

# input and output that once lost data or passed silently (tests/tools/hardening.sh)
foreach(check ini bench-ini lost-checkpoint trace links stdout)
  add_test(NAME tools/hardening_${check}
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/tools/hardening.sh $<TARGET_FILE:duel_evolve> $<TARGET_FILE:neat_bench>
                   ${CMAKE_CURRENT_SOURCE_DIR}/tools/coev-small.ini ${check})
endforeach()


# faults: every write, fsync and rename of a short run and its resume failing in turn (an LD_PRELOAD shim)
add_library(fault_shim MODULE tools/fault_shim.c)
target_compile_options(fault_shim PRIVATE -Wall -Wextra -Werror) # not -Wpedantic: it casts dlsym's void *
target_link_libraries(fault_shim PRIVATE ${CMAKE_DL_LIBS})
set_target_properties(fault_shim PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/tests)
# (every call in the normal build; every 8th under the sanitizers, where a run is several times slower, and
# the smaller populations there: 230 s with coev-small.ini at -O0)
if(NEAT_SANITIZE)
  set(NEAT_FAULT_STRIDE 8)
  set(NEAT_FAULT_CFG ${CMAKE_CURRENT_SOURCE_DIR}/tools/coev-small-asan.ini)
else()
  set(NEAT_FAULT_STRIDE 1)
  set(NEAT_FAULT_CFG ${CMAKE_CURRENT_SOURCE_DIR}/tools/coev-small.ini)
endif()
# OSMesa's own leaks (tests/render/lsan.supp) suppressed under the sanitizer build: every test that renders
set(NEAT_RENDER_ENV "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_SOURCE_DIR}/render/lsan.supp:print_suppressions=0")
# issue 40: files that are not ours, records rebuilt or refused, bounded reads, the lock (tests/tools/safety.sh;
# outputs and small render)
if(NEAT_SANITIZE)
  set(NEAT_SAFETY_PLAN ${CMAKE_CURRENT_SOURCE_DIR}/tools/tiny-plan-asan.ini)
else()
  set(NEAT_SAFETY_PLAN ${CMAKE_CURRENT_SOURCE_DIR}/tools/tiny-plan.ini)
endif()
foreach(check rundir lock bounds records outputs paths edits counters small)
  add_test(NAME tools/safety_${check}
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/tools/safety.sh $<TARGET_FILE:duel_evolve>
                   ${CMAKE_CURRENT_SOURCE_DIR}/tools/coev-small.ini ${NEAT_SAFETY_PLAN} ${check} $<TARGET_FILE:fault_shim>)
  set_tests_properties(tools/safety_${check} PROPERTIES ENVIRONMENT "${NEAT_RENDER_ENV}")
endforeach()

# issue 49: data safety, third pass (tests/tools/safety3.sh)
foreach(check runfiles dirs world plan scripts messages edits provenance records)
  add_test(NAME tools/safety3_${check}
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/tools/safety3.sh $<TARGET_FILE:duel_evolve>
                   ${CMAKE_CURRENT_SOURCE_DIR}/tools/coev-small.ini ${NEAT_SAFETY_PLAN} ${check})
  set_tests_properties(tools/safety3_${check} PROPERTIES ENVIRONMENT "${NEAT_RENDER_ENV}")
endforeach()

add_test(NAME tools/duel_run_faults
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/tools/fault.sh $<TARGET_FILE:duel_evolve> $<TARGET_FILE:fault_shim>
                 ${NEAT_FAULT_CFG} ${NEAT_FAULT_STRIDE})
set_tests_properties(tools/duel_run_faults PROPERTIES TIMEOUT 600)

# replays and rendering (OSMesa, libpng): pixels of known states and of a collision read back from the PNGs;
# duel_evolve render / render-net from the outside (frames, same bytes twice, LCM logs, ffmpeg video, bad input)
# OSMesa's own leaks (tests/render/lsan.supp) suppressed under the sanitizer build (NEAT_RENDER_ENV, above)
neat_add_test(render test_render)
target_link_libraries(test_render PRIVATE duelrender)
set_tests_properties(render/test_render PROPERTIES ENVIRONMENT "${NEAT_RENDER_ENV}")
# the web pages' writer (escaping, base64, a page with hostile names); the pages in Chromium, headless, through
# chromedriver and Debian's python3-selenium: every page kind, drawn state against play --trace and the runtime's
# hidden activations (the Python package steps them), no console message, no request, hostile names as text
neat_add_test(render test_html)
target_link_libraries(test_html PRIVATE duelhtml)
if(NEAT_PYTHON)
  add_test(NAME render/html_browser
           COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/render/html_browser.py $<TARGET_FILE:duel_evolve>
                   $<TARGET_FILE:duel_bench> ${CMAKE_CURRENT_SOURCE_DIR}/tools/fixtures/experiment-tiny
                   ${PROJECT_BINARY_DIR}/python ${PROJECT_BINARY_DIR}/tests/html-screenshots)
  set_tests_properties(render/html_browser PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 300)
endif()
# the same pages in Firefox ESR over WebDriver BiDi, where it is installed (scripts/deps.sh does not: skipped)
add_test(NAME render/html_firefox
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/render/html_firefox.py $<TARGET_FILE:duel_evolve>
                 $<TARGET_FILE:duel_bench> ${CMAKE_CURRENT_SOURCE_DIR}/tools/fixtures/experiment-tiny)
set_tests_properties(render/html_firefox PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 300)
add_test(NAME render/html_cli
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/render/html_cli.sh $<TARGET_FILE:duel_evolve> $<TARGET_FILE:duel_bench>
                 ${CMAKE_CURRENT_SOURCE_DIR}/tools/fixtures/experiment-tiny)
set_tests_properties(render/html_cli PROPERTIES ENVIRONMENT "${NEAT_RENDER_ENV}") # it draws frames too (OSMesa)
foreach(check frames deterministic lcm video video-kill render-net bad-input)
  add_test(NAME render/duel_render_${check}
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/render/render_cli.sh $<TARGET_FILE:duel_evolve> $<TARGET_FILE:duel_bench>
                   ${check})
  set_tests_properties(render/duel_render_${check} PROPERTIES SKIP_RETURN_CODE 77 ENVIRONMENT "${NEAT_RENDER_ENV}")
endforeach()

# duel_evolve export: the array compiled by the host compiler gives back the blob; bad input
# (the firmware example's own tests are in examples/firmware/test)
foreach(check roundtrip header bad-input)
  add_test(NAME tools/duel_export_${check}
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/tools/duel_export.sh $<TARGET_FILE:duel_evolve>
                   $<TARGET_FILE:duel_bench> ${check})
endforeach()

# LCM (tests/lcm): decoding, state messages, the nodes over memq://, event logs and replay frames in one
# process; from the outside: logs against play --trace, bad input, three processes over tcpq:// with LCM's
# Java hub on loopback, a killed controller, lcm-logplayer, run's champion games, the Python reader
neat_add_test(lcm test_lcm ${PROJECT_SOURCE_DIR}/bench/bench_nets.c lcm/hostile_msgs.c)
target_include_directories(test_lcm PRIVATE ${PROJECT_SOURCE_DIR}/bench ${CMAKE_CURRENT_SOURCE_DIR}/lcm)
# the hostile peer of the lcm/duel_lcm_hostile-* tests: crafted messages as logs or on a bus
add_executable(lcm_hostile lcm/lcm_hostile.c lcm/hostile_msgs.c)
target_compile_options(lcm_hostile PRIVATE ${NEAT_WARNINGS})
target_link_libraries(lcm_hostile PRIVATE duellcmtypes)
set_target_properties(lcm_hostile PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/tests)
target_link_libraries(test_lcm PRIVATE duellcm)
if(TARGET duelreplay) # duel_replay_from_game, to compare its frames with the log's
  target_link_libraries(test_lcm PRIVATE duelreplay)
  target_compile_definitions(test_lcm PRIVATE TL_HAVE_REPLAY_GAME)
endif()
find_program(NEAT_JAVA java)
pkg_get_variable(LCM_JAVA_CLASSPATH lcm-java classpath)
if(NOT LCM_JAVA_CLASSPATH)
  set(LCM_JAVA_CLASSPATH /usr/share/java/lcm.jar)
endif()
find_program(LCM_LOGPLAYER lcm-logplayer HINTS ${LCM_PREFIX}/bin NO_DEFAULT_PATH) # not PyPI lcm's, if on PATH
# Debian's python3 first (a python3 of pyenv or a virtual environment may lack matplotlib), and the PyPI lcm
# package where scripts/deps.sh puts it
set(NEAT_PYTHON3 ${DUEL_PYTHON})
set(NEAT_PY_LCM "$ENV{HOME}/.local/lib/neat-duel/python3" CACHE PATH "the PyPI lcm package's directory (scripts/deps.sh)")
foreach(check log bad-input processes kill logplayer champion-games python hostile-logs hostile-bus)
  add_test(NAME lcm/duel_lcm_${check}
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/lcm/lcm_cli.sh ${check} $<TARGET_FILE:duel_evolve> $<TARGET_FILE:duel_bench>
                   ${NEAT_JAVA} ${LCM_JAVA_CLASSPATH} ${LCM_LOGPLAYER} ${NEAT_PYTHON3} ${DUEL_LCM_GEN}/python
                   ${CMAKE_CURRENT_SOURCE_DIR}/tools/coev-small.ini $<TARGET_FILE:lcm_hostile>)
  set_tests_properties(lcm/duel_lcm_${check} PROPERTIES SKIP_RETURN_CODE 77 ENVIRONMENT "NEAT_PY_LCM=${NEAT_PY_LCM}")
endforeach()

# duel_evolve under mpirun (docs/cluster.md), when duel_evolve is built with MPI and mpirun is there: 1, 2, 3 and 5
# ranks give one process's files; a killed rank, Ctrl-C, resumes with another N; bad launches (mpi_skew: a rank of
# another build, DUEL_MPI_SALT)
find_program(MPIRUN mpirun)
if(MPI_C_FOUND AND MPIRUN)
  add_executable(mpi_skew tools/mpi_skew.c ${DUEL_MPI_SOURCES} ${PROJECT_SOURCE_DIR}/tools/common/duel_games.c ${PROJECT_SOURCE_DIR}/tools/common/duel_text.c
                 ${PROJECT_SOURCE_DIR}/tools/common/duel_child.c)
  target_include_directories(mpi_skew PRIVATE ${PROJECT_SOURCE_DIR}/tools/mpi ${PROJECT_SOURCE_DIR}/tools/common)
  target_compile_options(mpi_skew PRIVATE ${NEAT_WARNINGS})
  target_compile_definitions(mpi_skew PRIVATE DUEL_MPI_SALT=1 DUEL_VERSION="${PROJECT_VERSION}")
  find_package(Threads REQUIRED)
  target_link_libraries(mpi_skew PRIVATE neattools duelsim MPI::MPI_C Threads::Threads)
  foreach(check run experiment faults bad)
    add_test(NAME tools/mpi_${check}
             COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/tools/mpi.sh $<TARGET_FILE:duel_evolve> ${check}
                     ${CMAKE_CURRENT_SOURCE_DIR}/tools/coev-small.ini ${CMAKE_CURRENT_SOURCE_DIR}/tools/tiny-plan.ini
                     $<TARGET_FILE:mpi_skew>)
    set_tests_properties(tools/mpi_${check} PROPERTIES TIMEOUT 600)
  endforeach()
endif()

# --version: the project's version (project() above), one line on stdout
add_test(NAME tools/duel_evolve_version COMMAND duel_evolve --version)
add_test(NAME tools/neat_bench_version COMMAND neat_bench --version)
set_tests_properties(tools/duel_evolve_version PROPERTIES PASS_REGULAR_EXPRESSION "^duel_evolve ${PROJECT_VERSION} \\(duel world v1 b43972def416b019")
set_tests_properties(tools/neat_bench_version PROPERTIES PASS_REGULAR_EXPRESSION "^neat_bench ${PROJECT_VERSION} \\(libneat")
# neat_bench TASK --help: the options described (exit 0), not "--help needs a value"
add_test(NAME tools/neat_bench_help COMMAND neat_bench xor --help)
set_tests_properties(tools/neat_bench_help PROPERTIES PASS_REGULAR_EXPRESSION "  --dump-config +print the parameters")

# the deterministic figures the docs quote (code sizes, instructions per step, stack, evaluation counts), each
# marked <!--fig:NAME--> in README.md and docs/*.md, measured again: a stale one fails the test
# (scripts/doc_figures.py BUILD --write puts the measured ones in place)
if(NOT NEAT_SANITIZE AND NOT NEAT_FUZZ)
  add_test(NAME docs/figures COMMAND ${DUEL_PYTHON} ${PROJECT_SOURCE_DIR}/scripts/doc_figures.py ${PROJECT_BINARY_DIR})
  set_tests_properties(docs/figures PROPERTIES SKIP_RETURN_CODE 77)
endif()

# every command block of README.md, run as written in order (long jobs smaller: tests/docs/readme_commands.sh)
if(NOT NEAT_SANITIZE AND NOT NEAT_FUZZ)
  add_test(NAME docs/readme_commands
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/docs/readme_commands.sh ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR})
  # the longest test (about 150 s): started first, beside the others
  set_tests_properties(docs/readme_commands PROPERTIES COST 1000)
  # and every command block of docs/*.md, a test per doc with commands (docs/commands/NAME), each after the README's
  # set-up: made once by docs/commands/setup (the fixture) into docs-setup/, each doc's test runs in a copy of it
  set(docs_setup ${CMAKE_CURRENT_BINARY_DIR}/docs-setup)
  add_test(NAME docs/commands/setup
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/docs/readme_commands.sh ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR}
                   --setup ${docs_setup})
  add_test(NAME docs/commands/cleanup COMMAND ${CMAKE_COMMAND} -E rm -rf ${docs_setup})
  set_tests_properties(docs/commands/setup PROPERTIES FIXTURES_SETUP docs_setup COST 900)
  set_tests_properties(docs/commands/cleanup PROPERTIES FIXTURES_CLEANUP docs_setup)
  file(GLOB docs CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/docs/*.md)
  foreach(doc ${docs})
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${doc}) # a block made ```sh adds its test
    file(STRINGS ${doc} sh_blocks REGEX "^```sh$")
    if(sh_blocks)
      get_filename_component(name ${doc} NAME_WE)
      add_test(NAME docs/commands/${name}
               COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/docs/readme_commands.sh ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR}
                       ${doc} ${docs_setup})
      set_tests_properties(docs/commands/${name} PROPERTIES FIXTURES_REQUIRED docs_setup)
    endif()
  endforeach()
  # docs/lcm.md's commands while another process holds the port they name (issue 42)
  add_test(NAME docs/commands/lcm-port-taken
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/docs/port_taken.sh ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR}
                   ${PROJECT_SOURCE_DIR}/docs/lcm.md ${docs_setup})
  set_tests_properties(docs/commands/lcm-port-taken PROPERTIES FIXTURES_REQUIRED docs_setup SKIP_RETURN_CODE 77)
  # the experiment's doc plays two whole plans (about 90 s of CPU): started early too
  if(TEST docs/commands/experiment)
    set_tests_properties(docs/commands/experiment PROPERTIES COST 800)
  endif()
endif()
