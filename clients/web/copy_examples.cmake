# cmake -DSOURCE=proto/examples -DDESTINATION=DIR -P copy_examples.cmake: copies the example
# scenes (with the files they name) for the viewer's "open an example", and writes
# DESTINATION/index.json: [{"name", "path"}], one per scene file, named after its folder or file.
file(REMOVE_RECURSE ${DESTINATION})
file(COPY ${SOURCE}/ DESTINATION ${DESTINATION})
file(GLOB_RECURSE scenes RELATIVE ${SOURCE} ${SOURCE}/*.json)
list(SORT scenes)
set(items "")
foreach(path ${scenes})
  get_filename_component(folder ${path} DIRECTORY)
  get_filename_component(name ${path} NAME_WE)
  if(folder)
    set(name ${folder})
  endif()
  list(APPEND items "{\"name\": \"${name}\", \"path\": \"${path}\"}")
endforeach()
list(JOIN items ",\n  " body)
file(WRITE ${DESTINATION}/index.json "[\n  ${body}\n]\n")
