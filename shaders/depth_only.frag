#version 330 core
// depth_only.frag - the depth pre-pass writes depth and nothing else.

void main()
{
}
