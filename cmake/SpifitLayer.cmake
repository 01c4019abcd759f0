# One static library per layer of the source tree (docs/design/architecture.md, "Layers").
#
# spifit_layer(TARGET DIR [DEPS layer...] [PUBLIC_LIBS ...] [PRIVATE_LIBS ...] [EXCLUDE file...])
#
# Compiles every .cpp under DIR and gives the library, as its only include path of the
# project, a directory of its own in the build tree that holds a link to DIR alone
# (build/layers/TARGET/DIR -> DIR). A file includes another layer's header as
# "forward/io/csv_writer.hpp", and that path resolves only through the include directories
# of the layers it links (CMake passes PUBLIC include directories on with the link): a
# header of a layer that is not below it is "No such file" at compile time, so the
# dependency order is checked by the compiler (tests/layering checks that it is).
function(spifit_layer target dir)
  cmake_parse_arguments(L "" "" "DEPS;PUBLIC_LIBS;PRIVATE_LIBS;EXCLUDE" ${ARGN})
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${dir}/*.cpp)
  foreach(x ${L_EXCLUDE})
    list(REMOVE_ITEM sources ${PROJECT_SOURCE_DIR}/${dir}/${x})
  endforeach()
  set(root ${PROJECT_BINARY_DIR}/layers/${target})
  get_filename_component(parent ${root}/${dir} DIRECTORY)
  file(MAKE_DIRECTORY ${parent})
  if(NOT EXISTS ${root}/${dir})
    file(CREATE_LINK ${PROJECT_SOURCE_DIR}/${dir} ${root}/${dir} SYMBOLIC)
  endif()
  if(sources)
    add_library(${target} STATIC ${sources})
    target_include_directories(${target} PUBLIC ${root})
    target_link_libraries(${target} PUBLIC ${L_DEPS} ${L_PUBLIC_LIBS} PRIVATE ${L_PRIVATE_LIBS} spifit_warnings)
  else()
    add_library(${target} INTERFACE)
    target_include_directories(${target} INTERFACE ${root})
    target_link_libraries(${target} INTERFACE ${L_DEPS} ${L_PUBLIC_LIBS})
  endif()
endfunction()
