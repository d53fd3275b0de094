# The pipeline's internal layers: a folder of pipeline/ may include headers of its own folder and
# of folders below it in this order, never of a folder above it or beside it (same rank):
#
#   core < scene < bounds < cluster < io < proxy < select, view < eval < export < graph < doc
#
# core: errors, progress, atomic files. scene: the scene model. bounds: spheres, boxes, overlap
# volumes. cluster: the clusterers and the tree. io: importers and the GLB writer. proxy: proxy
# baking and its statistics. select / view: LOD selection / tree views for the editor (siblings,
# neither needs the other). eval: benchmarks and plots. export: the package. graph: parameters
# declared as data and the pipeline graph that runs the stages. doc: the document (commands,
# undo, project files) over the graph.
#
# Known exceptions (file -> header, and why) are listed in `allowed_exceptions`; anything else
# that reaches up fails with the file, the header and the rule. A new folder must be given a
# rank here before it can be used (the check names it).
#
# Run by ctest (architecture.pipeline_layers): cmake -DSOURCE_DIR=<repo>/pipeline -P this file.
cmake_minimum_required(VERSION 3.20)
set(layers core scene bounds cluster io proxy "select|view" eval export graph doc)

# io/Import.cpp opens an exported package folder as a scene (`hlod info PACKAGE`, File ▸ Open
# of a package): the reader lives in export/, beside the writer it mirrors.
set(allowed_exceptions "io/Import.cpp>export/Package.h")

set(rank 0)
foreach(entry IN LISTS layers)
  string(REPLACE "|" ";" names "${entry}")
  foreach(name IN LISTS names)
    set(rank_of_${name} ${rank})
  endforeach()
  math(EXPR rank "${rank} + 1")
endforeach()

file(GLOB_RECURSE sources RELATIVE ${SOURCE_DIR} ${SOURCE_DIR}/*.h ${SOURCE_DIR}/*.cpp)
set(problems "")
set(checked 0)
foreach(src IN LISTS sources)
  string(REGEX MATCH "^[^/]+" folder "${src}")
  if(folder STREQUAL src)
    continue() # files at the top of pipeline/ (none today) belong to no layer
  endif()
  if(NOT DEFINED rank_of_${folder})
    list(APPEND problems "pipeline/${folder}/ has no layer: give it a rank in ${CMAKE_CURRENT_LIST_FILE}")
    continue()
  endif()
  file(STRINGS ${SOURCE_DIR}/${src} includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"pipeline/")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "^[^\"]*\"pipeline/([^\"]+)\".*$" "\\1" header "${line}")
    string(REGEX MATCH "^[^/]+" target "${header}")
    math(EXPR checked "${checked} + 1")
    if(target STREQUAL folder)
      continue()
    endif()
    if(NOT DEFINED rank_of_${target})
      list(APPEND problems "pipeline/${src} includes pipeline/${header}: ${target}/ has no layer")
      continue()
    endif()
    if(rank_of_${target} LESS rank_of_${folder})
      continue()
    endif()
    if("${src}>${header}" IN_LIST allowed_exceptions)
      continue()
    endif()
    if(rank_of_${target} EQUAL rank_of_${folder})
      set(why "${folder}/ and ${target}/ are siblings")
    else()
      set(why "${target}/ is a layer above ${folder}/")
    endif()
    list(APPEND problems "pipeline/${src} includes pipeline/${header} (${why})")
  endforeach()
endforeach()

if(problems)
  list(JOIN problems "\n  " text)
  message(FATAL_ERROR "the pipeline's layers are broken (order: ${layers}):\n  ${text}")
endif()
message(STATUS "pipeline layers hold: ${checked} includes checked (order: ${layers})")
