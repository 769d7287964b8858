package raytracer.io.obj;

import java.io.IOException;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.ForkJoinTask;
import java.util.concurrent.RecursiveTask;

/**
 * Reading and parsing side by side: the calling thread inflates and cuts the text into chunks, the
 * chunks are parsed as fork/join tasks ({@link PlainChunk}), and the results are handed back on the
 * calling thread in file order. The tasks run in the pool the caller runs in (the command line's
 * one pool, sized by --threads), or in the common pool when the caller is in none. On the dragon
 * (2 cores) parsing beside the reading took the parse from 0.77-0.90 s to 0.64-0.78 s; most of the
 * rest is the JIT and the collector, which already kept the second core half busy during a serial
 * read. Run in the command line's pool of 2 instead of a pool of its own beside the reading
 * thread, the parse took 0.885 times as long (median of 36 interleaved pairs on a shared host);
 * having the reading thread parse the newest chunks while it waits for the oldest did not help.
 * Each chunk's buffer and the scratch arrays of its parse go back to be used again once it is
 * merged ({@link LineChunks#recycle}, {@link PlainChunk.Scratch}).
 */
final class ChunkPipeline {
    /** Takes a chunk's text and its plain parse, in file order. */
    interface Merge {
        void append(Decoding.Text text, PlainChunk chunk) throws ObjException;
    }

    private ChunkPipeline() {
    }

    /**
     * Parses the chunks in parallel while this thread inflates and cuts the next ones, then appends
     * their results in file order. A file of one chunk is parsed on this thread alone.
     */
    static void run(LineChunks chunks, Merge merge) throws IOException, ObjException {
        Decoding.Text first = chunks.next();
        Decoding.Text second = first != null ? chunks.next() : null;
        if (second == null) {
            if (first != null) {
                merge.append(first, PlainChunk.parse(first.chars(), new PlainChunk.Scratch()));
            }
            return;
        }
        // a chunk per worker and one more keep the workers busy; more only hold text and scratch,
        // which, filling the young generation during the parse, were copied into the old one: with
        // 2 + 2 per worker the 3.5 M-triangle mesh peaked at 341 MiB of heap, with 1 + 1 at 248
        int ahead = parallelism() + 1;
        Deque<Parse> inFlight = new ArrayDeque<>();
        Deque<PlainChunk.Scratch> scratch = new ArrayDeque<>();
        Pipe pipe = new Pipe(chunks, merge, inFlight, scratch);
        try {
            inFlight.add(Parse.fork(first, scratchFrom(scratch)));
            inFlight.add(Parse.fork(second, scratchFrom(scratch)));
            Decoding.Text text;
            while ((text = nextChunk(pipe)) != null) {
                while (inFlight.size() > ahead) {
                    mergeOldest(pipe);
                }
                inFlight.add(Parse.fork(text, scratchFrom(scratch)));
            }
            while (!inFlight.isEmpty()) {
                mergeOldest(pipe);
            }
        } finally {
            // after an error, the chunks not yet parsed need not be
            inFlight.forEach(parse -> parse.cancel(false));
        }
    }

    /** Workers of the pool the chunks are parsed in. */
    private static int parallelism() {
        return ForkJoinTask.inForkJoinPool() ? ForkJoinTask.getPool().getParallelism()
                                             : ForkJoinPool.getCommonPoolParallelism();
    }

    /** What the reading and merging thread works with. */
    private record Pipe(LineChunks chunks, Merge merge, Deque<Parse> inFlight, Deque<PlainChunk.Scratch> scratch) {
    }

    private static PlainChunk.Scratch scratchFrom(Deque<PlainChunk.Scratch> spare) {
        PlainChunk.Scratch s = spare.poll();
        return s != null ? s : new PlainChunk.Scratch();
    }

    /** The next chunk; when the stream fails, the chunks read before it come first, with their errors. */
    private static Decoding.Text nextChunk(Pipe pipe) throws IOException, ObjException {
        try {
            return pipe.chunks().next();
        } catch (IOException e) {
            while (!pipe.inFlight().isEmpty()) {
                mergeOldest(pipe);
            }
            throw e;
        }
    }

    /** Merges the oldest chunk in flight, then takes back its buffer and scratch for the chunks to come. */
    private static void mergeOldest(Pipe pipe) throws ObjException {
        Parse oldest = pipe.inFlight().remove();
        pipe.merge().append(oldest.text, oldest.join());
        pipe.chunks().recycle(oldest.text);
        pipe.scratch().add(oldest.scratch);
    }

    /** The plain parse of one chunk, as a task of the caller's pool. */
    private static final class Parse extends RecursiveTask<PlainChunk> {
        private static final long serialVersionUID = 1L;
        private final transient Decoding.Text text;
        private final transient PlainChunk.Scratch scratch;

        private Parse(Decoding.Text text, PlainChunk.Scratch scratch) {
            this.text = text;
            this.scratch = scratch;
        }

        static Parse fork(Decoding.Text text, PlainChunk.Scratch scratch) {
            Parse parse = new Parse(text, scratch);
            parse.fork();
            return parse;
        }

        @Override
        protected PlainChunk compute() {
            return PlainChunk.parse(text.chars(), scratch);
        }
    }
}
