# --camera: any pose, headless, through the scene parser's camera line; the attributes not given
# keep the scene's values.
if(TARGET 07_face_culling AND TARGET 00_forward)
  # The scene's own eye and target again: the same picture, byte for byte.
  course_agreement_test(camera_scene_pose 0 0
    07_face_culling --camera "eye 5.5 4.2 7.5 target 0.3 0.4 0" VS 07_face_culling)
  # Another pose: deferred still matches forward, and the picture is not the default one.
  course_forward_agreement_test(camera_pose_07 1 0.0001 07_face_culling --camera "eye 8 3 2")
  chapters_04_07_expect_bug(camera_pose_moves 07_face_culling --camera "eye 8 3 2" VS 07_face_culling)
  # A bad pose is refused with the camera line's own message.
  add_test(NAME cli.camera_bad_up
    COMMAND 07_face_culling --headless --size 32x24 --camera "eye 0 10 0 target 0 0 0"
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(cli.camera_bad_up PROPERTIES LABELS golden
    PASS_REGULAR_EXPRESSION "--camera:1: camera: up \\(0 1 0\\) is zero or parallel")
endif()
