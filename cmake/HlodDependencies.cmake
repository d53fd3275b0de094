# Every dependency comes from Debian 12's packages (scripts/install-deps.sh installs them).
find_package(Threads REQUIRED)
# libdeflate: the PNG writer's deflate (pipeline/io/ThirdPartyImpl.cpp), smaller and faster than
# zlib's best level.
find_package(PkgConfig REQUIRED)
pkg_check_modules(LIBDEFLATE REQUIRED IMPORTED_TARGET libdeflate)
find_package(glm REQUIRED)
find_package(TBB REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
find_package(assimp REQUIRED)
find_package(OpenCASCADE REQUIRED)
find_package(meshoptimizer REQUIRED)
find_package(OpenMesh REQUIRED)

# OpenVDB ships its Find module in its own cmake folder.
foreach(dir /usr/lib/x86_64-linux-gnu/cmake/OpenVDB /usr/lib/cmake/OpenVDB)
  if(EXISTS ${dir}/FindOpenVDB.cmake)
    list(APPEND CMAKE_MODULE_PATH ${dir})
  endif()
endforeach()
find_package(OpenVDB REQUIRED)

# tinygltf 2.7 (header) includes stb_image.h from libstb-dev's stb folder.
find_path(TINYGLTF_INCLUDE_DIR tiny_gltf.h REQUIRED)
find_path(STB_INCLUDE_DIR stb_image.h PATHS /usr/include/stb REQUIRED)

if(HLOD_BUILD_GUI)
  find_package(Qt6 REQUIRED COMPONENTS Core Gui Widgets OpenGL OpenGLWidgets LinguistTools Test)
  # Debian's VTK needs MPI's C target before VTK's exported targets configure.
  find_package(MPI COMPONENTS C)
  find_package(VTK 9.1 REQUIRED COMPONENTS CommonCore CommonDataModel CommonColor
               FiltersSources FiltersCore FiltersGeneral InteractionStyle RenderingCore
               RenderingOpenGL2 RenderingAnnotation RenderingFreeType RenderingContextOpenGL2
               IOImage)
endif()

if(HLOD_BUILD_TESTS)
  find_package(GTest REQUIRED)
  include(GoogleTest)
endif()
if(HLOD_BUILD_BENCHMARKS)
  find_package(benchmark REQUIRED)
endif()
