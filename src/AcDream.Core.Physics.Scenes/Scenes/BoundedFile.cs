using System;
using System.IO;
using System.Text;

namespace AcDream.Core.Physics.Scenes;

/// <summary>
/// Reading the tool's input files with caps: a file is checked before it is opened (a regular file of at
/// most a cap's size; a FIFO or a device would block or never end), read to at most its cap, and a gzip
/// stream is inflated to at most its cap. Every refusal is a <see cref="SceneFormatException"/> with an
/// empty JSON path, which the tool prints after the file's name on one line.
/// </summary>
internal static class BoundedFile
{
    /// <summary>The largest scene file read, bytes (the real-cell scenes are under 80 KB).</summary>
    public const long MaxSceneBytes = 32L << 20;

    /// <summary>The largest trajectory file read, bytes (a scene's 200 000 frames in all write about 80 MB).</summary>
    public const long MaxTrajectoryBytes = 256L << 20;

    /// <summary>The largest parity file read, compressed bytes (the ACE files are under 1 MB).</summary>
    public const long MaxParityBytes = 64L << 20;

    /// <summary>The most a parity file may inflate to, bytes (the ACE files inflate to about 9 MB; the whole text is held while it is parsed).</summary>
    public const long MaxParityInflatedBytes = 64L << 20;

    /// <summary>
    /// Refuses, before opening it, a path that is not a regular file of 1 to <paramref name="maxBytes"/>
    /// bytes (following symbolic links). A FIFO, a socket or a device reports a size of 0, as an empty file
    /// does: each is refused without being opened, so nothing blocks.
    /// </summary>
    public static void CheckRegular(string path, long maxBytes, string kind)
    {
        ArgumentNullException.ThrowIfNull(path);
        FileSystemInfo info = new FileInfo(path);
        if (info.LinkTarget is not null)
            info = File.ResolveLinkTarget(path, returnFinalTarget: true) ?? info;
        if (info is not FileInfo file || !file.Exists)
            throw new SceneFormatException(string.Empty, "does not exist or is not a file.");
        if (file.Length == 0)
            throw new SceneFormatException(string.Empty, "is empty or not a regular file (a FIFO, a socket or a device); not read.");
        if (file.Length > maxBytes)
            throw new SceneFormatException(string.Empty, $"is {file.Length} bytes; a {kind} may be at most {maxBytes} bytes.");
    }

    /// <summary>
    /// The text of a checked file (<see cref="CheckRegular"/>), decoded as <see cref="File.ReadAllText(string)"/>
    /// does (UTF-8 unless a byte-order mark says otherwise), reading at most <paramref name="maxBytes"/>
    /// bytes even when the file grows after the check.
    /// </summary>
    public static string ReadText(string path, long maxBytes, string kind)
    {
        CheckRegular(path, maxBytes, kind);
        using var file = File.OpenRead(path);
        using var capped = new CappedStream(file, maxBytes, $"a {kind} may be at most {maxBytes} bytes");
        using var reader = new StreamReader(capped, Encoding.UTF8, detectEncodingFromByteOrderMarks: true);
        return reader.ReadToEnd();
    }

    /// <summary>A read-only stream that refuses to give more than a number of bytes.</summary>
    internal sealed class CappedStream(Stream inner, long cap, string refusal) : Stream
    {
        private long _read;

        public override bool CanRead => true;
        public override bool CanSeek => false;
        public override bool CanWrite => false;
        public override long Length => throw new NotSupportedException();
        public override long Position { get => _read; set => throw new NotSupportedException(); }

        public override int Read(byte[] buffer, int offset, int count) => Read(buffer.AsSpan(offset, count));

        public override int Read(Span<byte> buffer)
        {
            // Ask for one byte past the cap at most, so a stream of exactly the cap is read whole.
            long room = cap - _read + 1;
            int n = inner.Read(room < buffer.Length ? buffer[..(int)room] : buffer);
            _read += n;
            if (_read > cap)
                throw new SceneFormatException(string.Empty, $"holds more than {cap} bytes; {refusal}.");
            return n;
        }

        public override void Flush() { }
        public override long Seek(long offset, SeekOrigin origin) => throw new NotSupportedException();
        public override void SetLength(long value) => throw new NotSupportedException();
        public override void Write(byte[] buffer, int offset, int count) => throw new NotSupportedException();

        protected override void Dispose(bool disposing)
        {
            if (disposing)
                inner.Dispose();
            base.Dispose(disposing);
        }
    }
}
