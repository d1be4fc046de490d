# Included by tools/plot/CMakeLists.txt: the page of `koppel catalog page`. Its template and
# script, and its search module (the catalog library's text_search.cpp compiled by em++ into one
# JavaScript file with the module inlined), are embedded into koppel_plot as the other pages are
# (tools/view/embed.cmake). Without em++ (or in a checked build) the page is written without its
# search box's module, and says so.
set(page_dir ${CMAKE_CURRENT_LIST_DIR}/../catalog_page)
set(catalog_assets ${CMAKE_BINARY_DIR}/tools/catalog_page/catalog_page_assets.cpp)
set(names TEMPLATE,SCRIPT)
set(module_args "")
set(module_depends "")
if(KOPPEL_EMXX AND NOT KOPPEL_SANITIZE AND NOT KOPPEL_FUZZ)
  set(search_dir ${CMAKE_BINARY_DIR}/tools/catalog_page)
  set(search_module ${search_dir}/koppel_search.js)
  file(MAKE_DIRECTORY ${search_dir})
  set(search_sources ${page_dir}/search_module.cpp ${CMAKE_SOURCE_DIR}/catalog/src/text_search.cpp)
  add_custom_command(
    OUTPUT ${search_module}
    COMMAND ${CMAKE_COMMAND} -E env NODE_PATH=/usr/share/nodejs ${KOPPEL_EMXX} -std=c++20 -O2 -I${CMAKE_SOURCE_DIR}/catalog/include
            ${search_sources} -o ${search_module} -sMODULARIZE=1 -sEXPORT_NAME=KoppelSearch -sSINGLE_FILE=1 -sENVIRONMENT=web,node
            -sEXPORTED_FUNCTIONS=_koppel_search_score -sEXPORTED_RUNTIME_METHODS=ccall
    DEPENDS ${search_sources} ${CMAKE_SOURCE_DIR}/catalog/include/koppel/catalog/text_search.hpp
    COMMENT "em++: the catalog page's search module" VERBATIM)
  add_custom_target(koppel_catalog_search_module DEPENDS ${search_module})
  add_dependencies(koppel_plot koppel_catalog_search_module)
  set(names TEMPLATE,SCRIPT,MODULE)
  set(module_args -D MODULE=${search_module})
  set(module_depends ${search_module})
  target_compile_definitions(koppel_plot PRIVATE KOPPEL_CATALOG_SEARCH=1)
  set(KOPPEL_CATALOG_SEARCH ON CACHE INTERNAL "the catalog page's search module is built (em++ found)")
else()
  target_compile_definitions(koppel_plot PRIVATE KOPPEL_CATALOG_SEARCH=0)
  set(KOPPEL_CATALOG_SEARCH OFF CACHE INTERNAL "the catalog page's search module is built (em++ found)")
endif()
add_custom_command(
  OUTPUT ${catalog_assets}
  COMMAND ${CMAKE_COMMAND} -D NAMES=${names} -D NAMESPACE=koppel::plot::catalog_assets -D TEMPLATE=${page_dir}/page.html
          -D SCRIPT=${page_dir}/catalog_page.js ${module_args} -D OUTPUT=${catalog_assets} -P ${CMAKE_SOURCE_DIR}/tools/view/embed.cmake
  DEPENDS ${page_dir}/page.html ${page_dir}/catalog_page.js ${module_depends} ${CMAKE_SOURCE_DIR}/tools/view/embed.cmake
  COMMENT "Embedding the page of koppel catalog page" VERBATIM)
target_sources(koppel_plot PRIVATE ${catalog_assets})
set_source_files_properties(${catalog_assets} PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
