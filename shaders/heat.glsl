// heat.glsl - the overdraw views' colour map (chapters 03-07, key V): how many times a pixel was lit,
// as a colour. 0 is black; 1 to SHADER_HEAT_MAX (16) climb a perceptual ramp (matplotlib's
// "inferno" from 0.2 to 1: purple, red, orange, yellow, pale yellow) in equal steps; SHADER_HEAT_MAX
// and more are all the last colour. The colours are display values: write them as they are.
// tools/heat_count.c renders this function to read a screenshot back into counts.
#ifndef HEAT_GLSL
#define HEAT_GLSL

const vec3 HEAT_RAMP[9] = vec3[9](vec3(66, 10, 104), vec3(106, 23, 110), vec3(147, 38, 103),
                                  vec3(188, 55, 84), vec3(221, 81, 58), vec3(243, 120, 25),
                                  vec3(252, 165, 10), vec3(246, 215, 70), vec3(252, 255, 164));

vec3 heat(int count)
{
    if (count <= 0)
        return vec3(0.0);
    float x = 8.0 * float(min(count, SHADER_HEAT_MAX) - 1) / float(SHADER_HEAT_MAX - 1);
    int i = min(int(x), 7);
    return mix(HEAT_RAMP[i], HEAT_RAMP[i + 1], x - float(i)) / 255.0;
}

// A count target's value as a count: the overdraw view adds 1 / SHADER_OVERDRAW_SCALE per fragment.
int overdraw_count(float sum)
{
    return int(round(sum * float(SHADER_OVERDRAW_SCALE)));
}

#endif
