# Included by tools/plot/CMakeLists.txt: a generated source must be made in the directory of
# the target that compiles it.
# The page of `koppel view`: uPlot comes from the npm registry, pinned by package-lock.json and
# fetched by `npm ci` at build time (with playwright-core and pngjs for the browser test); the page
# template, its script and uPlot with its licence are compiled into koppel_plot, so the page
# opens offline and the executable needs no files beside it.
find_program(KOPPEL_NPM npm REQUIRED)
set(KOPPEL_VIEW_NODE_DIR ${CMAKE_BINARY_DIR}/tools/view/npm CACHE INTERNAL "node_modules of the page build")
file(MAKE_DIRECTORY ${KOPPEL_VIEW_NODE_DIR})
set(uplot ${KOPPEL_VIEW_NODE_DIR}/node_modules/uplot)
set(mathjs ${KOPPEL_VIEW_NODE_DIR}/node_modules/mathjs)  # the editor page's formulas (tools/edit/edit.cmake)
# Without the tests only uPlot is fetched (the browser test's playwright-core and pngjs are
# devDependencies); the stamp, the rule's first output, names which, so that turning the tests on
# fetches them.
if(BUILD_TESTING)
  set(npm_omit "")
  set(npm_stamp ${KOPPEL_VIEW_NODE_DIR}/npm-ci-with-tests.stamp)
else()
  set(npm_omit --omit=dev)
  set(npm_stamp ${KOPPEL_VIEW_NODE_DIR}/npm-ci-page-only.stamp)
endif()
add_custom_command(
  OUTPUT ${npm_stamp} ${uplot}/dist/uPlot.iife.min.js ${uplot}/dist/uPlot.min.css ${uplot}/LICENSE ${mathjs}/lib/browser/math.js ${mathjs}/LICENSE
  COMMAND ${CMAKE_COMMAND} -E rm -f ${KOPPEL_VIEW_NODE_DIR}/npm-ci-with-tests.stamp ${KOPPEL_VIEW_NODE_DIR}/npm-ci-page-only.stamp
  COMMAND ${CMAKE_COMMAND} -E copy ${CMAKE_CURRENT_LIST_DIR}/package.json ${CMAKE_CURRENT_LIST_DIR}/package-lock.json ${KOPPEL_VIEW_NODE_DIR}
  COMMAND ${KOPPEL_NPM} ci ${npm_omit} --ignore-scripts --no-audit --no-fund --loglevel=error
  COMMAND ${CMAKE_COMMAND} -E touch ${uplot}/dist/uPlot.iife.min.js ${uplot}/dist/uPlot.min.css ${uplot}/LICENSE ${mathjs}/lib/browser/math.js ${mathjs}/LICENSE ${npm_stamp}
  WORKING_DIRECTORY ${KOPPEL_VIEW_NODE_DIR}
  DEPENDS ${CMAKE_CURRENT_LIST_DIR}/package.json ${CMAKE_CURRENT_LIST_DIR}/package-lock.json
  COMMENT "npm ci: uPlot (and math.js) for the pages of koppel view and koppel edit"
  VERBATIM)
set(assets ${CMAKE_BINARY_DIR}/tools/view/view_assets.cpp)
add_custom_command(
  OUTPUT ${assets}
  COMMAND ${CMAKE_COMMAND} -D TEMPLATE=${CMAKE_CURRENT_LIST_DIR}/page.html -D SCRIPT=${CMAKE_CURRENT_LIST_DIR}/view.js
          -D UPLOT_JS=${uplot}/dist/uPlot.iife.min.js -D UPLOT_CSS=${uplot}/dist/uPlot.min.css -D UPLOT_LICENSE=${uplot}/LICENSE
          -D OUTPUT=${assets} -P ${CMAKE_CURRENT_LIST_DIR}/embed.cmake
  DEPENDS ${CMAKE_CURRENT_LIST_DIR}/page.html ${CMAKE_CURRENT_LIST_DIR}/view.js ${CMAKE_CURRENT_LIST_DIR}/embed.cmake
          ${npm_stamp} ${uplot}/dist/uPlot.iife.min.js ${uplot}/dist/uPlot.min.css ${uplot}/LICENSE
  COMMENT "Embedding the page of koppel view"
  VERBATIM)
target_sources(koppel_plot PRIVATE ${assets})
