# `cmake --install` exports matpredict::matbase, matpredict::matmaterial, matpredict::matgeom, matpredict::matrender, matpredict::matlearn_metrics, matpredict::matlearn_isolation,
# matpredict::matdataset_format, matpredict::matdataset_maker and matpredict::matlearn (libtorch) for find_package(matpredict).
include(CMakePackageConfigHelpers)
install(TARGETS matbase matmaterial matgeom matrender matdataset_format matdataset_maker matlearn_metrics matlearn_isolation matlearn EXPORT matpredictTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY libmatbase/include/matbase libmatmaterial/include/matmaterial libmatgeom/include/matgeom libmatrender/include/matrender libmatdataset/include/matdataset libmatlearn/include/matlearn
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT matpredictTargets NAMESPACE matpredict::
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/matpredict)
configure_package_config_file(cmake/matpredictConfig.cmake.in
        ${CMAKE_CURRENT_BINARY_DIR}/matpredictConfig.cmake
        INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/matpredict)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/matpredictConfigVersion.cmake
        COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/matpredictConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/matpredictConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/matpredict)
