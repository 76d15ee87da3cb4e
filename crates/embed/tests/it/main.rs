mod embeddings;
mod sight;
