// SPDX-License-Identifier: Apache-2.0
// A Transform is read on Unity's main thread once a frame (60-90 Hz), a tool is posed on
// the physics thread every millisecond. Posting the frame's pose as it comes would move the
// tool in one 1 ms step by what the hand moved in a frame, and hold it still for the rest:
// a jolt per frame in the contact forces. Instead the main thread keeps the last two frame
// samples, stamped with the Stopwatch, and the physics thread plays them back a little
// behind (the delay, about a frame), interpolating between them: the tool moves smoothly
// at 1 kHz, one frame late. A sequence lock hands the samples over: the main thread never
// waits, and the physics thread retries in the rare case it reads during a write.
using System.Threading;

namespace Enteron.Unity
{
    /// <summary>One writer thread posts timed poses; one reader thread samples them at any time, interpolated.</summary>
    public sealed class PoseInterpolator
    {
        private struct Sample
        {
            internal long Time;  // Stopwatch ticks
            internal Vec3 Position;
            internal Quat Orientation;
        }

        private Sample _older;
        private Sample _newer;
        private int _count;    // samples written, up to 2
        private int _version;  // odd while a write is in progress

        /// <summary>The writer (one thread): the pose at Stopwatch time <paramref name="time"/>.</summary>
        public void Write(long time, Vec3 position, Quat orientation)
        {
            Interlocked.Increment(ref _version);  // odd: readers retry (a full fence)
            _older = _newer;
            _newer = new Sample { Time = time, Position = position, Orientation = orientation };
            if (_count < 2) ++_count;
            Interlocked.Increment(ref _version);  // even again
        }

        /// <summary>
        /// The reader (one thread): the pose at Stopwatch time <paramref name="time"/>, linear
        /// between the two samples (normalised-linear for the rotation), held before the older
        /// and after the newer. False until the first sample.
        /// </summary>
        public bool Read(long time, out Vec3 position, out Quat orientation)
        {
            Sample older, newer;
            int count;
            for (;;)
            {
                int version = Volatile.Read(ref _version);
                if ((version & 1) != 0)
                {
                    Thread.SpinWait(1);
                    continue;
                }
                older = _older;
                newer = _newer;
                count = _count;
                Thread.MemoryBarrier();
                if (Volatile.Read(ref _version) == version) break;
            }
            if (count == 0)
            {
                position = Vec3.Zero;
                orientation = Quat.Identity;
                return false;
            }
            if (count == 1 || newer.Time <= older.Time || time >= newer.Time)
            {
                position = newer.Position;
                orientation = newer.Orientation;
                return true;
            }
            double alpha = time <= older.Time ? 0.0 : (double)(time - older.Time) / (newer.Time - older.Time);
            position = older.Position + alpha * (newer.Position - older.Position);
            orientation = Nlerp(older.Orientation, newer.Orientation, alpha);
            return true;
        }

        /// <summary>(1 - a) p + a q along the shorter way (q and -q are one rotation), normalised.</summary>
        private static Quat Nlerp(Quat p, Quat q, double a)
        {
            double sign = p.W * q.W + p.X * q.X + p.Y * q.Y + p.Z * q.Z < 0 ? -1.0 : 1.0;
            var r = new Quat((1 - a) * p.W + sign * a * q.W, (1 - a) * p.X + sign * a * q.X,
                             (1 - a) * p.Y + sign * a * q.Y, (1 - a) * p.Z + sign * a * q.Z);
            double norm = System.Math.Sqrt(r.W * r.W + r.X * r.X + r.Y * r.Y + r.Z * r.Z);
            return norm > 0 ? new Quat(r.W / norm, r.X / norm, r.Y / norm, r.Z / norm) : p;
        }
    }
}
