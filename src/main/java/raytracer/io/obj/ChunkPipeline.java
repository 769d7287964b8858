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
                merge.append(first, PlainChunk.parse(first.text()));
            }
            return;
        }
        // a few chunks ahead keep the workers busy; more would only hold text in memory
        int ahead = 2 * parallelism() + 2;
        Deque<Parse> inFlight = new ArrayDeque<>();
        try {
            inFlight.add(Parse.fork(first));
            inFlight.add(Parse.fork(second));
            Decoding.Text text;
            while ((text = nextChunk(chunks, inFlight, merge)) != null) {
                while (inFlight.size() > ahead) {
                    mergeOldest(inFlight, merge);
                }
                inFlight.add(Parse.fork(text));
            }
            while (!inFlight.isEmpty()) {
                mergeOldest(inFlight, merge);
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

    /** The next chunk; when the stream fails, the chunks read before it come first, with their errors. */
    private static Decoding.Text nextChunk(LineChunks chunks, Deque<Parse> inFlight, Merge merge)
            throws IOException, ObjException {
        try {
            return chunks.next();
        } catch (IOException e) {
            while (!inFlight.isEmpty()) {
                mergeOldest(inFlight, merge);
            }
            throw e;
        }
    }

    private static void mergeOldest(Deque<Parse> inFlight, Merge merge) throws ObjException {
        Parse oldest = inFlight.remove();
        merge.append(oldest.text, oldest.join());
    }

    /** The plain parse of one chunk, as a task of the caller's pool. */
    private static final class Parse extends RecursiveTask<PlainChunk> {
        private static final long serialVersionUID = 1L;
        private final transient Decoding.Text text;

        private Parse(Decoding.Text text) {
            this.text = text;
        }

        static Parse fork(Decoding.Text text) {
            Parse parse = new Parse(text);
            parse.fork();
            return parse;
        }

        @Override
        protected PlainChunk compute() {
            return PlainChunk.parse(text.text());
        }
    }
}
