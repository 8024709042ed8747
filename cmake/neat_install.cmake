# neat_install.cmake - cmake --install: the libraries and their public headers (include/neat_duel/), the CMake
# package (find_package(neat_duel CONFIG) -> neat_duel::nrt, ::duelsim, ::neat, ::duelengine), pkg-config files
# (nrt.pc, duelsim.pc, neat.pc, duelengine.pc), LICENSE, and duel_evolve and neat_bench when they are built.
# docs/library.md.
include(CMakePackageConfigHelpers)

set(NEAT_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/neat_duel)
install(TARGETS nrt duelsim neat duelengine EXPORT neat_duelTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(FILES ${PROJECT_SOURCE_DIR}/runtime/include/neat_duel_version.h ${PROJECT_SOURCE_DIR}/runtime/include/nrt.h
              ${PROJECT_SOURCE_DIR}/runtime/include/nrt_dense.h ${PROJECT_SOURCE_DIR}/duelsim/include/duel.h
              ${PROJECT_SOURCE_DIR}/libneat/include/neat.h ${PROJECT_SOURCE_DIR}/libneat/include/neat_coev.h
              ${PROJECT_SOURCE_DIR}/libneat/include/neat_phenotype.h
              ${PROJECT_SOURCE_DIR}/tools/run/duel_engine.h ${PROJECT_SOURCE_DIR}/tools/common/duel_config.h
        DESTINATION ${NEAT_INSTALL_INCLUDEDIR})
install(EXPORT neat_duelTargets NAMESPACE neat_duel:: DESTINATION ${NEAT_CMAKE_DIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/neat_duelConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/neat_duelConfig.cmake INSTALL_DESTINATION ${NEAT_CMAKE_DIR})
# 0.x: a newer minor version may break what an older one had (as the SONAME says)
if(PROJECT_VERSION_MAJOR EQUAL 0)
  set(_compat SameMinorVersion)
else()
  set(_compat SameMajorVersion)
endif()
write_basic_package_version_file(${PROJECT_BINARY_DIR}/neat_duelConfigVersion.cmake COMPATIBILITY ${_compat})
install(FILES ${PROJECT_BINARY_DIR}/neat_duelConfig.cmake ${PROJECT_BINARY_DIR}/neat_duelConfigVersion.cmake
        DESTINATION ${NEAT_CMAKE_DIR})

# pkg-config: relative to the .pc file's own directory (${pcfiledir}), so that cmake --install --prefix anywhere
# gives working files. nrt is Requires (not .private): the users of neat and duelsim call nrt_* themselves.
set(NEAT_PC_DIR ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
  set(PC_PREFIX_REL "")
  message(WARNING "CMAKE_INSTALL_LIBDIR is absolute: the pkg-config files are not relocatable")
else()
  file(RELATIVE_PATH PC_PREFIX_REL /prefix/${NEAT_PC_DIR} /prefix)
endif()
set(PC_CFLAGS "")
if(BUILD_SHARED_LIBS)
  set(PC_CFLAGS " -DNEAT_DUEL_SHARED") # the declarations' export attribute, as the libraries were built
endif()
foreach(PC_NAME nrt duelsim neat duelengine)
  if(PC_NAME STREQUAL "nrt")
    set(PC_DESC "neat-duel controller runtime: champion blobs stepped in fixed point, no malloc")
    set(PC_REQUIRES "")
    set(PC_LIBS_PRIVATE "")
  elseif(PC_NAME STREQUAL "duelsim")
    set(PC_DESC "neat-duel robot duel world (spec v1), integer arithmetic")
    set(PC_REQUIRES "nrt = ${PROJECT_VERSION}")
    set(PC_LIBS_PRIVATE "")
  elseif(PC_NAME STREQUAL "duelengine")
    set(PC_DESC "neat-duel run engine: a duel coevolution in a run directory, generation by generation")
    set(PC_REQUIRES "neat = ${PROJECT_VERSION}, duelsim = ${PROJECT_VERSION}, nrt = ${PROJECT_VERSION}")
    set(PC_LIBS_PRIVATE "-pthread -lm")
  else()
    set(PC_DESC "NEAT and competitive coevolution (Stanley & Miikkulainen)")
    set(PC_REQUIRES "nrt = ${PROJECT_VERSION}")
    set(PC_LIBS_PRIVATE "-lm")
  endif()
  configure_file(${CMAKE_CURRENT_LIST_DIR}/neat_duel.pc.in ${PROJECT_BINARY_DIR}/pkgconfig/${PC_NAME}.pc @ONLY)
  install(FILES ${PROJECT_BINARY_DIR}/pkgconfig/${PC_NAME}.pc DESTINATION ${NEAT_PC_DIR})
endforeach()

install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR})
if(NEAT_BUILD_TOOLS)
  if(BUILD_SHARED_LIBS AND NOT IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
    # the installed tools find the installed shared libraries beside them, wherever the prefix is
    file(RELATIVE_PATH _bin_to_lib /prefix/${CMAKE_INSTALL_BINDIR} /prefix/${CMAKE_INSTALL_LIBDIR})
    set_target_properties(duel_evolve neat_bench PROPERTIES INSTALL_RPATH "$ORIGIN/${_bin_to_lib}")
  endif()
  install(TARGETS duel_evolve neat_bench RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
