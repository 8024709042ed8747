# neat_library.cmake - what the three libraries (nrt, duelsim, neat) share as installable targets: the
# neat_duel:: alias, include directories for the build and the install tree, the shared library's version and
# the export rules. Included by the top CMakeLists.txt; each library's own CMakeLists.txt calls neat_library().

# 0.x: every minor release may change the ABI, so the SONAME carries major.minor (libneat.so.0.16); from 1.0 on,
# the major alone
if(PROJECT_VERSION_MAJOR EQUAL 0)
  set(NEAT_SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
else()
  set(NEAT_SOVERSION ${PROJECT_VERSION_MAJOR})
endif()
# where the public headers go: one directory of their own, so that "nrt.h" and "duel.h" clash with nothing
set(NEAT_INSTALL_INCLUDEDIR ${CMAKE_INSTALL_INCLUDEDIR}/neat_duel)

function(neat_library lib)
  add_library(neat_duel::${lib} ALIAS ${lib}) # the installed package's name, in a tree or a parent project too
  target_include_directories(${lib} PUBLIC $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
                             $<INSTALL_INTERFACE:${NEAT_INSTALL_INCLUDEDIR}>)
  set_target_properties(${lib} PROPERTIES VERSION ${PROJECT_VERSION} SOVERSION ${NEAT_SOVERSION})
  get_target_property(_type ${lib} TYPE)
  if(_type STREQUAL "SHARED_LIBRARY")
    # only what the public headers mark NRT_API / NEAT_API / DUEL_API is exported (neat_duel_version.h);
    # NEAT_DUEL_SHARED reaches the libraries' users too, whose declarations then say the same
    set_target_properties(${lib} PROPERTIES C_VISIBILITY_PRESET hidden)
    target_compile_definitions(${lib} PUBLIC NEAT_DUEL_SHARED)
  endif()
endfunction()
