# SPDX-License-Identifier: Apache-2.0
# Assembles the Unity package from bindings/unity and the build (target enteron_unity_package):
#   cmake -DSOURCE=<repo> -DOUTPUT=<dir>/com.enteron.unity -DTARBALL=<file>.tgz -DASSEMBLY=Enteron.dll
#         -DLIBRARY=libenteron.so.0 -P assemble_package.cmake
# The folder is what Unity's Package Manager opens ("Add package from disk": its package.json)
# and the tarball ("Add package from tarball"; files under package/, as npm packs them):
#   package.json, Documentation~/, Runtime/*.cs + Enteron.Unity.asmdef
#   Runtime/Plugins/Enteron.dll, Enteron.xml      the binding (managed: any platform)
#   Runtime/Plugins/x86_64/libenteron.so          this build's library (Linux x86-64 only)
#   Samples~/Abdomen/                             the sample, with Scenes/abdomen.json and its organs
# and a .meta beside every file and folder Unity imports (all but the ~ folders): Unity
# refuses an asset without one in a package it cannot write to. Each GUID is the MD5 of the
# asset's path in the package, so a rebuild gives the same GUIDs.
cmake_minimum_required(VERSION 3.20)
foreach(variable SOURCE OUTPUT TARBALL ASSEMBLY LIBRARY)
  if(NOT DEFINED ${variable})
    message(FATAL_ERROR "assemble_package.cmake: -D${variable}=... is missing")
  endif()
endforeach()
set(unity "${SOURCE}/bindings/unity")
file(REMOVE_RECURSE "${OUTPUT}")
file(MAKE_DIRECTORY "${OUTPUT}/Runtime/Plugins/x86_64" "${OUTPUT}/Samples~/Abdomen/Scenes")
file(COPY "${unity}/package.json" "${unity}/README.md" DESTINATION "${OUTPUT}")
file(COPY "${unity}/Documentation~" DESTINATION "${OUTPUT}")
file(GLOB runtime "${unity}/Runtime/*.cs" "${unity}/Runtime/*.asmdef")
file(COPY ${runtime} DESTINATION "${OUTPUT}/Runtime")
get_filename_component(assembly_dir "${ASSEMBLY}" DIRECTORY)
file(COPY "${ASSEMBLY}" "${assembly_dir}/Enteron.xml" DESTINATION "${OUTPUT}/Runtime/Plugins")
file(COPY_FILE "${LIBRARY}" "${OUTPUT}/Runtime/Plugins/x86_64/libenteron.so")  # the file, not the symlink
file(COPY "${unity}/Samples~/Abdomen" DESTINATION "${OUTPUT}/Samples~")
file(COPY "${SOURCE}/examples/scenes/abdomen.json" "${SOURCE}/examples/scenes/organs"
     DESTINATION "${OUTPUT}/Samples~/Abdomen/Scenes")

set(tail "  externalObjects: {}\n  userData: \n  assetBundleName: \n  assetBundleVariant: \n")
function(write_meta path)
  file(RELATIVE_PATH relative "${OUTPUT}" "${path}")
  string(MD5 guid "com.enteron.unity/${relative}")
  get_filename_component(extension "${path}" LAST_EXT)
  if(IS_DIRECTORY "${path}")
    set(importer "folderAsset: yes\nDefaultImporter:\n${tail}")
  elseif(extension STREQUAL ".cs")
    set(importer "MonoImporter:\n  externalObjects: {}\n  serializedVersion: 2\n  defaultReferences: []\n  executionOrder: 0\n  icon: {instanceID: 0}\n  userData: \n  assetBundleName: \n  assetBundleVariant: \n")
  elseif(extension STREQUAL ".asmdef")
    set(importer "AssemblyDefinitionImporter:\n${tail}")
  elseif(extension STREQUAL ".dll")
    # Managed: every platform, referenced by every assembly (the samples use it directly).
    set(importer "PluginImporter:\n  externalObjects: {}\n  serializedVersion: 2\n  iconMap: {}\n  executionOrder: {}\n  defineConstraints: []\n  isPreloaded: 0\n  isOverridable: 0\n  isExplicitlyReferenced: 0\n  validateReferences: 1\n  platformData:\n  - first:\n      Any: \n    second:\n      enabled: 1\n      settings: {}\n  userData: \n  assetBundleName: \n  assetBundleVariant: \n")
  elseif(extension STREQUAL ".so")
    # Native, Linux x86-64: the Editor on Linux and Linux players.
    set(importer "PluginImporter:\n  externalObjects: {}\n  serializedVersion: 2\n  iconMap: {}\n  executionOrder: {}\n  defineConstraints: []\n  isPreloaded: 0\n  isOverridable: 0\n  isExplicitlyReferenced: 0\n  validateReferences: 1\n  platformData:\n  - first:\n      Any: \n    second:\n      enabled: 0\n      settings: {}\n  - first:\n      Editor: Editor\n    second:\n      enabled: 1\n      settings:\n        CPU: x86_64\n        DefaultValueInitialized: true\n        OS: Linux\n  - first:\n      Standalone: Linux64\n    second:\n      enabled: 1\n      settings:\n        CPU: x86_64\n  userData: \n  assetBundleName: \n  assetBundleVariant: \n")
  else()
    set(importer "TextScriptImporter:\n${tail}")
  endif()
  file(WRITE "${path}.meta" "fileFormatVersion: 2\nguid: ${guid}\n${importer}")
endfunction()
file(GLOB_RECURSE assets LIST_DIRECTORIES true "${OUTPUT}/*")
foreach(asset IN LISTS assets)
  if(NOT asset MATCHES "~(/|$)")  # Unity ignores the ~ folders until a sample is imported
    write_meta("${asset}")
  endif()
endforeach()

# The tarball: package/<files>, sorted names, fixed time and owner: the same bytes from the same tree.
get_filename_component(output_parent "${OUTPUT}" DIRECTORY)
set(staging "${output_parent}/tarball")
file(REMOVE_RECURSE "${staging}")
file(COPY "${OUTPUT}/" DESTINATION "${staging}/package")
execute_process(COMMAND tar --sort=name --mtime=@0 --owner=0 --group=0 --numeric-owner -czf "${TARBALL}" package
                WORKING_DIRECTORY "${staging}" RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "tar failed: ${status}")
endif()
file(REMOVE_RECURSE "${staging}")
