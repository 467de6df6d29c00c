namespace AcDream.Core.Physics.Motion;

/// <summary>
/// One animation played by a motion (the DAT's AnimData: 16 bytes in a MotionData): which animation, which
/// frames of it, and how fast. The sequence multiplies the framerate by the motion's speed; a negative
/// framerate plays the frames backwards.
/// </summary>
/// <param name="AnimationId">The animation (0x03… file id).</param>
/// <param name="LowFrame">The first frame played, 0 or more.</param>
/// <param name="HighFrame">The last frame played; −1 means the animation's last frame.</param>
/// <param name="Framerate">Frames per second at speed 1; finite and not zero.</param>
public readonly record struct AnimData(uint AnimationId, int LowFrame, int HighFrame, float Framerate);
