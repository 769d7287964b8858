package raytracer.io.obj;

import java.io.IOException;
import java.io.InterruptedIOException;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.Map;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;

/**
 * Reading and parsing side by side: the calling thread inflates and cuts the text into chunks, a
 * pool of one worker per processor parses them ({@link PlainChunk}), and the results are handed
 * back on the calling thread in file order. On the dragon (2 cores) this took the parse from
 * 0.77-0.90 s to 0.64-0.78 s; most of the rest is the JIT and the collector, which already kept
 * the second core half busy during a serial read.
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
        int workers = Runtime.getRuntime().availableProcessors();
        ExecutorService pool = Executors.newFixedThreadPool(workers, task -> {
            Thread t = new Thread(task, "obj-parse");
            t.setDaemon(true);
            return t;
        });
        Deque<Map.Entry<Decoding.Text, Future<PlainChunk>>> inFlight = new ArrayDeque<>();
        try {
            inFlight.add(Map.entry(first, pool.submit(() -> PlainChunk.parse(first.text()))));
            inFlight.add(Map.entry(second, pool.submit(() -> PlainChunk.parse(second.text()))));
            Decoding.Text text;
            while ((text = nextChunk(chunks, inFlight, merge)) != null) {
                // a few chunks ahead keep the workers busy; more would only hold text in memory
                while (inFlight.size() > 2 * workers + 2) {
                    mergeOldest(inFlight, merge);
                }
                Decoding.Text chunk = text;
                inFlight.add(Map.entry(chunk, pool.submit(() -> PlainChunk.parse(chunk.text()))));
            }
            while (!inFlight.isEmpty()) {
                mergeOldest(inFlight, merge);
            }
        } finally {
            pool.shutdownNow();
        }
    }

    /** The next chunk; when the stream fails, the chunks read before it come first, with their errors. */
    private static Decoding.Text nextChunk(LineChunks chunks, Deque<Map.Entry<Decoding.Text, Future<PlainChunk>>> inFlight,
                                    Merge merge)
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

    private static void mergeOldest(Deque<Map.Entry<Decoding.Text, Future<PlainChunk>>> inFlight, Merge merge)
            throws IOException, ObjException {
        Map.Entry<Decoding.Text, Future<PlainChunk>> oldest = inFlight.remove();
        try {
            merge.append(oldest.getKey(), oldest.getValue().get());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new InterruptedIOException("interrupted while parsing");
        } catch (ExecutionException e) {
            throw new IllegalStateException(e.getCause());
        }
    }
}
