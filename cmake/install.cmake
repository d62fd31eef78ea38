# cmake --install: the libraries, their public headers, the rdmesh command (with
# its CAD module) and
# the CMake package (rdmeshConfig.cmake) that exports rdmesh::rdmesh and rdmesh::cad.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# rdmesh::rdmesh: everything but CAD (the target "rdmesh" is the command).
add_library(rdmesh_library INTERFACE)
target_link_libraries(rdmesh_library INTERFACE rdmesh_io rdmesh_view rdmesh_core rdmesh_oracles rdmesh_base)
set_target_properties(rdmesh_library PROPERTIES EXPORT_NAME rdmesh)
set_target_properties(rdmesh_cad PROPERTIES EXPORT_NAME cad)
foreach(layer base oracles core view io)
  set_target_properties(rdmesh_${layer} PROPERTIES EXPORT_NAME ${layer})
endforeach()

install(TARGETS rdmesh_library rdmesh_io rdmesh_view rdmesh_core rdmesh_oracles rdmesh_base rdmesh_cad
        EXPORT rdmeshTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS rdmesh RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The command's CAD support, loaded from there (cli/CMakeLists.txt: RDMESH_CAD_MODULE_DIR).
install(TARGETS rdmesh_cad_module LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/rdmesh)
foreach(layer base oracles core view io cad)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${layer}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endforeach()

set(RDMESH_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/rdmesh)
install(EXPORT rdmeshTargets NAMESPACE rdmesh:: DESTINATION ${RDMESH_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/rdmeshConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/rdmeshConfig.cmake
                              INSTALL_DESTINATION ${RDMESH_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/rdmeshConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/rdmeshConfig.cmake ${PROJECT_BINARY_DIR}/rdmeshConfigVersion.cmake
        DESTINATION ${RDMESH_CMAKE_DIR})
